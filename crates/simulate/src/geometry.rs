//! Vectors and rotations in `f64` for the simulation; converted to the recording's `f32`
//! types only when a frame is written.

/// A 3D vector.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub(crate) struct V3 {
    pub x: f64,
    pub y: f64,
    pub z: f64,
}

impl V3 {
    pub const ZERO: V3 = V3::new(0.0, 0.0, 0.0);

    pub const fn new(x: f64, y: f64, z: f64) -> V3 {
        V3 { x, y, z }
    }

    pub fn dot(self, o: V3) -> f64 {
        self.x * o.x + self.y * o.y + self.z * o.z
    }

    pub fn norm(self) -> f64 {
        self.dot(self).sqrt()
    }

    pub fn horizontal(self) -> f64 {
        self.x.hypot(self.y)
    }

    pub fn cross(self, o: V3) -> V3 {
        V3::new(
            self.y * o.z - self.z * o.y,
            self.z * o.x - self.x * o.z,
            self.x * o.y - self.y * o.x,
        )
    }
}

impl std::ops::Add for V3 {
    type Output = V3;
    fn add(self, o: V3) -> V3 {
        V3::new(self.x + o.x, self.y + o.y, self.z + o.z)
    }
}

impl std::ops::AddAssign for V3 {
    fn add_assign(&mut self, o: V3) {
        *self = *self + o;
    }
}

impl std::ops::Sub for V3 {
    type Output = V3;
    fn sub(self, o: V3) -> V3 {
        V3::new(self.x - o.x, self.y - o.y, self.z - o.z)
    }
}

impl std::ops::Mul<f64> for V3 {
    type Output = V3;
    fn mul(self, s: f64) -> V3 {
        V3::new(self.x * s, self.y * s, self.z * s)
    }
}

impl std::ops::Neg for V3 {
    type Output = V3;
    fn neg(self) -> V3 {
        V3::new(-self.x, -self.y, -self.z)
    }
}

/// A unit quaternion (x, y, z, w).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Rot {
    pub x: f64,
    pub y: f64,
    pub z: f64,
    pub w: f64,
}

impl Rot {
    pub const IDENTITY: Rot = Rot {
        x: 0.0,
        y: 0.0,
        z: 0.0,
        w: 1.0,
    };

    /// Roll about x, then pitch about y, then yaw about z (extrinsic x-y-z, the ROS
    /// convention): `R = Rz(yaw) * Ry(pitch) * Rx(roll)`.
    pub fn from_euler(roll: f64, pitch: f64, yaw: f64) -> Rot {
        let (sr, cr) = (roll * 0.5).sin_cos();
        let (sp, cp) = (pitch * 0.5).sin_cos();
        let (sy, cy) = (yaw * 0.5).sin_cos();
        Rot {
            x: sr * cp * cy - cr * sp * sy,
            y: cr * sp * cy + sr * cp * sy,
            z: cr * cp * sy - sr * sp * cy,
            w: cr * cp * cy + sr * sp * sy,
        }
    }

    pub fn from_yaw(yaw: f64) -> Rot {
        let (s, c) = (yaw * 0.5).sin_cos();
        Rot {
            x: 0.0,
            y: 0.0,
            z: s,
            w: c,
        }
    }

    /// A rotation by the rotation vector `v` (axis times angle in radians).
    pub fn from_rotation_vector(v: V3) -> Rot {
        let angle = v.norm();
        if angle < 1e-12 {
            return Rot {
                x: v.x * 0.5,
                y: v.y * 0.5,
                z: v.z * 0.5,
                w: 1.0,
            }
            .normalised();
        }
        let (s, c) = (angle * 0.5).sin_cos();
        let k = s / angle;
        Rot {
            x: v.x * k,
            y: v.y * k,
            z: v.z * k,
            w: c,
        }
    }

    pub fn mul(self, o: Rot) -> Rot {
        Rot {
            w: self.w * o.w - self.x * o.x - self.y * o.y - self.z * o.z,
            x: self.w * o.x + self.x * o.w + self.y * o.z - self.z * o.y,
            y: self.w * o.y - self.x * o.z + self.y * o.w + self.z * o.x,
            z: self.w * o.z + self.x * o.y - self.y * o.x + self.z * o.w,
        }
    }

    pub fn conjugate(self) -> Rot {
        Rot {
            x: -self.x,
            y: -self.y,
            z: -self.z,
            w: self.w,
        }
    }

    pub fn normalised(self) -> Rot {
        let n = (self.x * self.x + self.y * self.y + self.z * self.z + self.w * self.w).sqrt();
        Rot {
            x: self.x / n,
            y: self.y / n,
            z: self.z / n,
            w: self.w / n,
        }
    }

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
    pub fn canonical(self) -> Rot {
        if self.w < 0.0 {
            Rot {
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
pub(crate) fn wrap_angle(a: f64) -> f64 {
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
        let a = Rot::from_euler(0.0, 0.0, 0.7);
        let b = Rot::from_yaw(0.7);
        assert!(
            (a.x - b.x).abs() + (a.y - b.y).abs() + (a.z - b.z).abs() + (a.w - b.w).abs() < 1e-12
        );
        let q = Rot::from_euler(0.1, -0.2, 0.3);
        let v = V3::new(0.3, -0.1, 0.5);
        let back = q.conjugate().rotate(q.rotate(v));
        assert!((back - v).norm() < 1e-12);
        assert!((q.mul(q.conjugate()).w - 1.0).abs() < 1e-12);
        assert!((Rot::from_euler(0.05, 0.02, 1.2).yaw() - 1.2).abs() < 0.01);
        assert!((wrap_angle(3.0 * std::f64::consts::PI) - std::f64::consts::PI).abs() < 1e-12);
    }
}
