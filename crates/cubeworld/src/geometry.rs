//! Quintic Hermite segments over [`geometry::V3`]: minimum jerk between two positions,
//! with given velocities at both ends.

use geometry::V3;

/// A quintic Hermite segment: from `p0` with velocity `v0` to `p1` with velocity `v1` in
/// `duration` seconds, zero acceleration at both ends (minimum jerk when both
/// velocities are zero; a straight line at constant speed when they agree with the
/// displacement).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Hermite {
    c: [V3; 6],
    /// Length in seconds.
    pub duration: f64,
}

impl Hermite {
    /// The segment; a duration below 1 ms is taken as 1 ms.
    pub fn new(p0: V3, v0: V3, p1: V3, v1: V3, duration: f64) -> Hermite {
        let t = duration.max(1e-3);
        let d = p1 - p0;
        let c3 = (d * 20.0 - (v1 * 8.0 + v0 * 12.0) * t) * (1.0 / (2.0 * t.powi(3)));
        let c4 = (d * -30.0 + (v1 * 14.0 + v0 * 16.0) * t) * (1.0 / (2.0 * t.powi(4)));
        let c5 = (d * 12.0 - (v1 + v0) * (6.0 * t)) * (1.0 / (2.0 * t.powi(5)));
        Hermite {
            c: [p0, v0, V3::ZERO, c3, c4, c5],
            duration: t,
        }
    }

    /// Position and velocity at time `s` (clamped to the segment).
    pub fn at(&self, s: f64) -> (V3, V3) {
        let s = s.clamp(0.0, self.duration);
        let c = &self.c;
        let p = c[0] + (c[1] + (c[2] + (c[3] + (c[4] + c[5] * s) * s) * s) * s) * s;
        let v = c[1] + (c[2] * 2.0 + (c[3] * 3.0 + (c[4] * 4.0 + c[5] * (5.0 * s)) * s) * s) * s;
        (p, v)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn close(a: V3, b: V3) -> bool {
        (a - b).norm() < 1e-9
    }

    #[test]
    fn hermite_meets_its_ends_and_is_linear_when_consistent() {
        let p0 = V3::new(0.1, 0.2, 0.3);
        let p1 = V3::new(0.4, -0.2, 0.9);
        let v0 = V3::new(0.1, 0.0, 0.0);
        let v1 = V3::new(0.0, 0.0, -0.2);
        let h = Hermite::new(p0, v0, p1, v1, 0.8);
        let (a, va) = h.at(0.0);
        let (b, vb) = h.at(0.8);
        assert!(close(a, p0) && close(va, v0) && close(b, p1) && close(vb, v1));
        // Constant velocity that matches the displacement: a straight line.
        let v = V3::new(0.15, 0.0, 0.0);
        let line = Hermite::new(p0, v, p0 + v * 0.5, v, 0.5);
        let (mid, vmid) = line.at(0.25);
        assert!(close(mid, p0 + v * 0.25) && close(vmid, v));
    }
}
