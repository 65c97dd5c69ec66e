//! Slurm: a grid written as an array job, a collect job and `submit.sh` (see `slurm`).
