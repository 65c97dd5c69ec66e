//! The `f64` geometry demoplan computes with: [`V3`], a point or vector, and [`Quat`], a
//! unit quaternion, in REP 103's conventions (metres, right-handed, z up, quaternions
//! written (x, y, z, w)). The simulator and the cube world share them; recordings store
//! `f32` (`recording::Vec3`, `recording::Quaternion`) and convert at their boundary.
//!
//! Every operation is written out component by component in a fixed order, so that the
//! same inputs give the same bits on every machine (the simulator's output bytes depend
//! on it).
//!
//! ```
//! use geometry::{Quat, V3};
//! let quarter = Quat::from_yaw(std::f64::consts::FRAC_PI_2);
//! let v = quarter.rotate(V3::new(1.0, 0.0, 0.0));
//! assert!((v - V3::new(0.0, 1.0, 0.0)).norm() < 1e-12);
//! ```

use std::ops::{Add, AddAssign, Mul, Neg, Sub};

/// A point or vector in metres (or metres per second), z up (REP 103, as recordings).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct V3 {
    /// Forward.
    pub x: f64,
    /// Left.
    pub y: f64,
    /// Up.
    pub z: f64,
}

impl V3 {
    /// The zero vector.
    pub const ZERO: V3 = V3::new(0.0, 0.0, 0.0);

    /// A vector from its components.
    pub const fn new(x: f64, y: f64, z: f64) -> V3 {
        V3 { x, y, z }
    }

    /// Dot product.
    pub fn dot(self, o: V3) -> f64 {
        self.x * o.x + self.y * o.y + self.z * o.z
    }

    /// Euclidean length.
    pub fn norm(self) -> f64 {
        self.dot(self).sqrt()
    }

    /// Length of the horizontal part, `hypot(x, y)`.
    pub fn horizontal_norm(self) -> f64 {
        self.x.hypot(self.y)
    }

    /// The horizontal part, scaled to length 1 (`fallback` when it is too short).
    pub fn horizontal_unit(self, fallback: V3) -> V3 {
        let n = self.horizontal_norm();
        if n < 1e-9 {
            fallback
        } else {
            V3::new(self.x / n, self.y / n, 0.0)
        }
    }

    /// Cross product.
    pub fn cross(self, o: V3) -> V3 {
        V3::new(
            self.y * o.z - self.z * o.y,
            self.z * o.x - self.x * o.z,
            self.x * o.y - self.y * o.x,
        )
    }

    /// The components `[x, y, z]`.
    pub fn to_array(self) -> [f64; 3] {
        [self.x, self.y, self.z]
    }
}

impl Add for V3 {
    type Output = V3;
    fn add(self, o: V3) -> V3 {
        V3::new(self.x + o.x, self.y + o.y, self.z + o.z)
    }
}

impl AddAssign for V3 {
    fn add_assign(&mut self, o: V3) {
        *self = *self + o;
    }
}

impl Sub for V3 {
    type Output = V3;
    fn sub(self, o: V3) -> V3 {
        V3::new(self.x - o.x, self.y - o.y, self.z - o.z)
    }
}

impl Mul<f64> for V3 {
    type Output = V3;
    fn mul(self, s: f64) -> V3 {
        V3::new(self.x * s, self.y * s, self.z * s)
    }
}

impl Neg for V3 {
    type Output = V3;
    fn neg(self) -> V3 {
        V3::new(-self.x, -self.y, -self.z)
    }
}

/// A unit quaternion (x, y, z, w).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Quat {
    /// The vector part's x.
    pub x: f64,
    /// The vector part's y.
    pub y: f64,
    /// The vector part's z.
    pub z: f64,
    /// The scalar part.
    pub w: f64,
}

impl Quat {
    /// No rotation.
    pub const IDENTITY: Quat = Quat {
        x: 0.0,
        y: 0.0,
        z: 0.0,
        w: 1.0,
    };

    /// Roll about x, then pitch about y, then yaw about z (extrinsic x-y-z, the ROS
    /// convention): `R = Rz(yaw) * Ry(pitch) * Rx(roll)`.
    pub fn from_euler(roll: f64, pitch: f64, yaw: f64) -> Quat {
        let (sr, cr) = (roll * 0.5).sin_cos();
        let (sp, cp) = (pitch * 0.5).sin_cos();
        let (sy, cy) = (yaw * 0.5).sin_cos();
        Quat {
            x: sr * cp * cy - cr * sp * sy,
            y: cr * sp * cy + sr * cp * sy,
            z: cr * cp * sy - sr * sp * cy,
            w: cr * cp * cy + sr * sp * sy,
        }
    }

    /// A rotation by `yaw` radians about z.
    pub fn from_yaw(yaw: f64) -> Quat {
        let (s, c) = (yaw * 0.5).sin_cos();
        Quat {
            x: 0.0,
            y: 0.0,
            z: s,
            w: c,
        }
    }

    /// A rotation by the rotation vector `v` (axis times angle in radians).
    pub fn from_rotation_vector(v: V3) -> Quat {
        let angle = v.norm();
        if angle < 1e-12 {
            return Quat {
                x: v.x * 0.5,
                y: v.y * 0.5,
                z: v.z * 0.5,
                w: 1.0,
            }
            .normalised();
        }
        let (s, c) = (angle * 0.5).sin_cos();
        let k = s / angle;
        Quat {
            x: v.x * k,
            y: v.y * k,
            z: v.z * k,
            w: c,
        }
    }

    /// The Hamilton product: `self` after `o`.
    #[allow(clippy::should_implement_trait)] // a named product, as the formulas read
    pub fn mul(self, o: Quat) -> Quat {
        Quat {
            w: self.w * o.w - self.x * o.x - self.y * o.y - self.z * o.z,
            x: self.w * o.x + self.x * o.w + self.y * o.z - self.z * o.y,
            y: self.w * o.y - self.x * o.z + self.y * o.w + self.z * o.x,
            z: self.w * o.z + self.x * o.y - self.y * o.x + self.z * o.w,
        }
    }

    /// The inverse rotation (of a unit quaternion).
    pub fn conjugate(self) -> Quat {
        Quat {
            x: -self.x,
            y: -self.y,
            z: -self.z,
            w: self.w,
        }
    }

    /// Scaled to length 1.
    pub fn normalised(self) -> Quat {
        let n = (self.x * self.x + self.y * self.y + self.z * self.z + self.w * self.w).sqrt();
        Quat {
            x: self.x / n,
            y: self.y / n,
            z: self.z / n,
            w: self.w / n,
        }
    }

    /// `v` rotated.
    pub fn rotate(self, v: V3) -> V3 {
        let q = V3::new(self.x, self.y, self.z);
        let t = q.cross(v) * 2.0;
        v + t * self.w + q.cross(t)
    }

    /// Heading: the rotation about z, in (-pi, pi].
    pub fn yaw(self) -> f64 {
        let siny = 2.0 * (self.w * self.z + self.x * self.y);
        let cosy = 1.0 - 2.0 * (self.y * self.y + self.z * self.z);
        siny.atan2(cosy)
    }

    /// The same rotation with non-negative w, so that written quaternions do not flip sign.
    pub fn canonical(self) -> Quat {
        if self.w < 0.0 {
            Quat {
                x: -self.x,
                y: -self.y,
                z: -self.z,
                w: -self.w,
            }
        } else {
            self
        }
    }
}

/// The angle `a` wrapped into (-pi, pi].
pub fn wrap_angle(a: f64) -> f64 {
    let tau = std::f64::consts::TAU;
    let r = a.rem_euclid(tau);
    if r > std::f64::consts::PI {
        r - tau
    } else {
        r
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn euler_yaw_matches_from_yaw_and_rotations_compose() {
        let a = Quat::from_euler(0.0, 0.0, 0.7);
        let b = Quat::from_yaw(0.7);
        assert!(
            (a.x - b.x).abs() + (a.y - b.y).abs() + (a.z - b.z).abs() + (a.w - b.w).abs() < 1e-12
        );
        let q = Quat::from_euler(0.1, -0.2, 0.3);
        let v = V3::new(0.3, -0.1, 0.5);
        let back = q.conjugate().rotate(q.rotate(v));
        assert!((back - v).norm() < 1e-12);
        assert!((q.mul(q.conjugate()).w - 1.0).abs() < 1e-12);
        assert!((Quat::from_euler(0.05, 0.02, 1.2).yaw() - 1.2).abs() < 0.01);
        assert!((wrap_angle(3.0 * std::f64::consts::PI) - std::f64::consts::PI).abs() < 1e-12);
    }
}
