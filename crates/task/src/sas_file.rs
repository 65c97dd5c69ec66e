//! Fast Downward's `output.sas` format.
