//! Motion primitives: minimum-jerk profiles, the arc of a movement, slow drift, and
//! tracking noise.
//!
//! A hand's path is a sum of minimum-jerk submovements (Flash and Hogan 1985; the
//! superposition model of Flash and Henis 1991): each moves the hand by a displacement
//! `D` over a duration `T` with the profile `s(τ) = 10τ³ − 15τ⁴ + 6τ⁵`. Submovements that
//! overlap in time blend into one smooth motion that does not stop in between (a grasp
//! on the fly, a reach redirected to another cube); separate ones stop in between.

use crate::rng::Rng;
use geometry::V3;

/// The minimum-jerk position profile on `τ ∈ [0, 1]` (clamped outside).
pub(crate) fn min_jerk(tau: f64) -> f64 {
    let t = tau.clamp(0.0, 1.0);
    t * t * t * (10.0 + t * (-15.0 + 6.0 * t))
}

/// Its derivative `ds/dτ = 30 τ² (1 − τ)²` (zero outside [0, 1]).
pub(crate) fn min_jerk_rate(tau: f64) -> f64 {
    if !(0.0..=1.0).contains(&tau) {
        return 0.0;
    }
    let u = tau * (1.0 - tau);
    30.0 * u * u
}

/// The arc of a movement: `64 τ³ (1 − τ)³`, 0 at both ends with zero velocity and
/// acceleration, 1 in the middle. A movement adds `arc * bump(τ)` to its height.
pub(crate) fn bump(tau: f64) -> f64 {
    if !(0.0..=1.0).contains(&tau) {
        return 0.0;
    }
    let u = tau * (1.0 - tau);
    64.0 * u * u * u
}

/// Its derivative `192 τ² (1 − τ)² (1 − 2τ)`.
pub(crate) fn bump_rate(tau: f64) -> f64 {
    if !(0.0..=1.0).contains(&tau) {
        return 0.0;
    }
    let u = tau * (1.0 - tau);
    192.0 * u * u * (1.0 - 2.0 * tau)
}

/// A smooth, slow wandering: per axis, a sum of three sinusoids with random periods and
/// phases, scaled to a root mean square amplitude. Deterministic in time, so that the
/// plan can aim movements knowing where the drift will be when they end.
#[derive(Debug, Clone)]
pub(crate) struct Drift {
    /// Per axis: (amplitude, angular frequency, phase) of each component.
    axes: [[(f64, f64, f64); 3]; 3],
}

impl Drift {
    /// `rms` per axis, periods drawn from `[period_min, period_max]`.
    pub fn new(rng: &mut Rng, rms: [f64; 3], period_min: f64, period_max: f64) -> Drift {
        let mut axes = [[(0.0, 0.0, 0.0); 3]; 3];
        for (axis, comps) in axes.iter_mut().enumerate() {
            // Three components of equal amplitude a have a mean square 3 a² / 2.
            let a = rms[axis] * (2.0f64 / 3.0).sqrt();
            for c in comps.iter_mut() {
                let period = rng.uniform(period_min, period_max);
                *c = (
                    a,
                    std::f64::consts::TAU / period,
                    rng.uniform(0.0, std::f64::consts::TAU),
                );
            }
        }
        Drift { axes }
    }

    fn axis(&self, axis: usize, t: f64) -> (f64, f64) {
        let mut p = 0.0;
        let mut v = 0.0;
        for &(a, w, phi) in &self.axes[axis] {
            let (s, c) = (w * t + phi).sin_cos();
            p += a * s;
            v += a * w * c;
        }
        (p, v)
    }

    /// Offset at time `t`.
    pub fn at(&self, t: f64) -> V3 {
        V3::new(self.axis(0, t).0, self.axis(1, t).0, self.axis(2, t).0)
    }

    /// Offset and its rate of change at time `t`.
    pub fn with_rate(&self, t: f64) -> (V3, V3) {
        let (x, vx) = self.axis(0, t);
        let (y, vy) = self.axis(1, t);
        let (z, vz) = self.axis(2, t);
        (V3::new(x, y, z), V3::new(vx, vy, vz))
    }
}

/// Tracking error that varies slowly: white noise through two first-order low-pass
/// filters in a row (time constant `tau`), scaled to a standard deviation `sd` per axis.
/// Its frame-to-frame changes are small, as with a tracker's filtered estimate.
#[derive(Debug, Clone)]
pub(crate) struct SlowNoise {
    a: f64,
    input_scale: f64,
    output_scale: f64,
    x1: V3,
    x2: V3,
}

impl SlowNoise {
    pub fn new(rng: &mut Rng, sd: f64, tau: f64, dt: f64) -> SlowNoise {
        let a = (-dt / tau).exp();
        // x1 is a unit-variance AR(1); x2 = a x2 + (1 − a) x1 has variance
        // (1 + a²) / (1 + a)².
        let var2 = (1.0 + a * a) / ((1.0 + a) * (1.0 + a));
        let mut n = SlowNoise {
            a,
            input_scale: (1.0 - a * a).sqrt(),
            output_scale: sd / var2.sqrt(),
            x1: V3::ZERO,
            x2: V3::ZERO,
        };
        // Start in the stationary distribution (approximately): a random state, then a
        // short run-in.
        n.x1 = V3::new(rng.normal(), rng.normal(), rng.normal());
        n.x2 = n.x1 * (var2.sqrt());
        for _ in 0..((3.0 * tau / dt) as usize).min(2000) {
            n.step(rng);
        }
        n
    }

    /// Advances one frame and returns the error.
    pub fn step(&mut self, rng: &mut Rng) -> V3 {
        let w = V3::new(rng.normal(), rng.normal(), rng.normal());
        self.x1 = self.x1 * self.a + w * self.input_scale;
        self.x2 = self.x2 * self.a + self.x1 * (1.0 - self.a);
        self.value()
    }

    /// The current error.
    pub fn value(&self) -> V3 {
        self.x2 * self.output_scale
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn profiles_start_and_end_at_rest() {
        assert_eq!(min_jerk(0.0), 0.0);
        assert!((min_jerk(1.0) - 1.0).abs() < 1e-12);
        assert!((min_jerk(0.5) - 0.5).abs() < 1e-12);
        assert_eq!(min_jerk_rate(0.0), 0.0);
        assert_eq!(min_jerk_rate(1.0), 0.0);
        // The peak rate is 1.875 at the middle.
        assert!((min_jerk_rate(0.5) - 1.875).abs() < 1e-12);
        assert!((bump(0.5) - 1.0).abs() < 1e-12);
        assert_eq!(bump(0.0), 0.0);
        // Rates are the derivatives.
        for i in 1..100 {
            let t = i as f64 / 100.0;
            let h = 1e-6;
            assert!(
                ((min_jerk(t + h) - min_jerk(t - h)) / (2.0 * h) - min_jerk_rate(t)).abs() < 1e-6
            );
            assert!(((bump(t + h) - bump(t - h)) / (2.0 * h) - bump_rate(t)).abs() < 1e-6);
        }
    }

    #[test]
    fn slow_noise_has_the_asked_spread() {
        let mut rng = Rng::new(3);
        let mut n = SlowNoise::new(&mut rng, 0.002, 0.25, 1.0 / 90.0);
        let xs: Vec<f64> = (0..90_000).map(|_| n.step(&mut rng).x).collect();
        let var = xs.iter().map(|x| x * x).sum::<f64>() / xs.len() as f64;
        assert!((var.sqrt() - 0.002).abs() < 0.0004, "{}", var.sqrt());
        let d = Drift::new(&mut rng, [0.01, 0.01, 0.0], 3.0, 12.0);
        let (p, v) = d.with_rate(1.0);
        let h = 1e-6;
        assert!(((d.at(1.0 + h).x - p.x) / h - v.x).abs() < 1e-6);
        assert_eq!(d.at(5.0).z, 0.0);
    }
}
