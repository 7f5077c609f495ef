//! Contacts with Coulomb friction, each with its closed form: a block on an incline, a mass on
//! a spring sliding on a floor, a mass on a spring riding a moving belt. Every scene is written
//! in world coordinates with a gap (the contact's normal) and a slip velocity (its tangent), as
//! a user would state them.

use zeitner::{constrained_system, Float};

/// A block (a point mass) on a plane through the origin inclined at `angle` (radians, rising
/// to the right), under gravity `g`, with friction coefficient `mu`. The gap is the distance from
/// the plane, the slip velocity the speed along it (positive up the slope).
#[derive(Clone, Debug)]
pub struct Incline {
    pub m: Float,
    pub g: Float,
    pub angle: Float,
    pub mu: Float,
}

#[constrained_system]
impl Incline {
    fn mass(&self) -> [Float; 2] {
        [self.m, self.m]
    }

    fn force(&self) -> [Float; 2] {
        [0.0, -self.m * self.g]
    }

    fn gaps(&self, [x, y]: [Float; 2]) -> [Float; 1] {
        [y * self.angle.cos() - x * self.angle.sin()]
    }

    fn slips(&self, _q: [Float; 2], [vx, vy]: [Float; 2]) -> [Float; 1] {
        [vx * self.angle.cos() + vy * self.angle.sin()]
    }

    fn friction(&self) -> [Float; 1] {
        [self.mu]
    }
}

impl Incline {
    /// Where the block is at `t`, released from rest at distance `s0` along the slope: up the
    /// slope `s0 - a t²/2` with `a = g (sin θ − μ cos θ)` where that is positive, `s0` (it sticks)
    /// where it is not. Returns `(x, y, ẋ, ẏ)`.
    pub fn released_at_rest(&self, s0: Float, t: Float) -> [Float; 4] {
        let (sin, cos) = self.angle.sin_cos();
        let a = (self.g * (sin - self.mu * cos)).max(0.0);
        let (s, ds) = (s0 - 0.5 * a * t * t, -a * t);
        [s * cos, s * sin, ds * cos, ds * sin]
    }

    /// When the block sent up the slope from the origin at `speed` stops: `v / g(sin θ + μ cos θ)`.
    pub fn stop_time(&self, speed: Float) -> Float {
        let (sin, cos) = self.angle.sin_cos();
        speed / (self.g * (sin + self.mu * cos))
    }

    /// Where the block is at `t`, sent up the slope from the origin at `speed`: decelerated by
    /// `g (sin θ + μ cos θ)` until [`Incline::stop_time`], then sliding down with
    /// `g (sin θ − μ cos θ)` where that is positive, else staying. Returns `(x, y, ẋ, ẏ)`.
    pub fn sent_up_the_slope(&self, speed: Float, t: Float) -> [Float; 4] {
        let (sin, cos) = self.angle.sin_cos();
        let up = self.g * (sin + self.mu * cos);
        let stop = self.stop_time(speed);
        let (s, ds) = if t <= stop {
            (speed * t - 0.5 * up * t * t, speed - up * t)
        } else {
            let top = speed * stop - 0.5 * up * stop * stop;
            let down = (self.g * (sin - self.mu * cos)).max(0.0);
            let after = t - stop;
            (top - 0.5 * down * after * after, -down * after)
        };
        [s * cos, s * sin, ds * cos, ds * sin]
    }

    /// The normal force the plane carries: `m g cos θ`.
    pub fn normal_force(&self) -> Float {
        self.m * self.g * self.angle.cos()
    }
}

/// A mass on a floor (`y ≥ 0`) held by a spring of stiffness `k` to `x = 0`, sliding with
/// friction `mu`: its swings shrink by `4 μ m g / k` a cycle, and it stops where the spring can
/// no longer overcome friction.
#[derive(Clone, Debug)]
pub struct SlidingOscillator {
    pub m: Float,
    pub g: Float,
    pub k: Float,
    pub mu: Float,
}

#[constrained_system]
impl SlidingOscillator {
    fn mass(&self) -> [Float; 2] {
        [self.m, self.m]
    }

    fn force(&self, [x, _y]: [Float; 2]) -> [Float; 2] {
        [-self.k * x, -self.m * self.g]
    }

    fn gaps(&self, [_x, y]: [Float; 2]) -> [Float; 1] {
        [y]
    }

    fn slips(&self, _q: [Float; 2], [vx, _vy]: [Float; 2]) -> [Float; 1] {
        [vx]
    }

    fn friction(&self) -> [Float; 1] {
        [self.mu]
    }
}

impl SlidingOscillator {
    /// `μ m g / k`: half the dead band in which the mass stays once it stops.
    pub fn dead_band(&self) -> Float {
        self.mu * self.m * self.g / self.k
    }

    /// The motion released from rest at `x0`, in closed form: each half-swing is a harmonic
    /// half-period about `±dead_band` (against the slip), ending at rest; the mass stops for good
    /// at the first rest inside the dead band. Returns `(x, ẋ)` at `t` and the time it stops.
    pub fn released_at_rest(&self, x0: Float, t: Float) -> ([Float; 2], Float) {
        let omega = (self.k / self.m).sqrt();
        let half = core::f64::consts::PI as Float / omega;
        let band = self.dead_band();
        let (mut x, mut start) = (x0, 0.0);
        loop {
            if x.abs() <= band {
                return ([x, 0.0], start);
            }
            // Slipping towards the spring's rest: friction pushes back, the centre moves.
            let centre = band * x.signum();
            if t < start + half {
                let phase = omega * (t - start);
                let amplitude = x - centre;
                let position = centre + amplitude * phase.cos();
                let velocity = -amplitude * omega * phase.sin();
                let stop = self.stop_time(x0);
                return ([position, velocity], stop);
            }
            x = 2.0 * centre - x;
            start += half;
        }
    }

    /// When the mass released from rest at `x0` stops for good.
    pub fn stop_time(&self, x0: Float) -> Float {
        let half = core::f64::consts::PI as Float / (self.k / self.m).sqrt();
        let band = self.dead_band();
        if band <= 0.0 {
            return Float::INFINITY;
        }
        let (mut x, mut stop) = (x0, 0.0);
        while x.abs() > band {
            x = 2.0 * band * x.signum() - x;
            stop += half;
        }
        stop
    }
}

/// A mass on a belt that moves at `belt` (`y ≥ 0` its surface), held by a spring of stiffness
/// `k` to `x = 0`, with friction `mu`. Started on the spring's rest point at the belt's speed it
/// rides along (sticks) until the spring's pull reaches `μ m g`, then slips for ever on a
/// harmonic swing whose slip speed comes back to zero once a period, just touching.
#[derive(Clone, Debug)]
pub struct Belt {
    pub m: Float,
    pub g: Float,
    pub k: Float,
    pub mu: Float,
    pub belt: Float,
}

#[constrained_system]
impl Belt {
    fn mass(&self) -> [Float; 2] {
        [self.m, self.m]
    }

    fn force(&self, [x, _y]: [Float; 2]) -> [Float; 2] {
        [-self.k * x, -self.m * self.g]
    }

    fn gaps(&self, [_x, y]: [Float; 2]) -> [Float; 1] {
        [y]
    }

    fn slips(&self, _q: [Float; 2], [vx, _vy]: [Float; 2]) -> [Float; 1] {
        [vx - self.belt]
    }

    fn friction(&self) -> [Float; 1] {
        [self.mu]
    }
}

impl Belt {
    /// A 1 kg mass on a 50 N/m spring riding a belt at 0.3 m/s with `μ = 0.4`: it slips at
    /// 0.2616 s.
    pub fn example() -> Self {
        Belt {
            m: 1.0,
            g: 9.81,
            k: 50.0,
            mu: 0.4,
            belt: 0.3,
        }
    }

    /// When the mass, started at `x = 0` at the belt's speed, starts to slip: `μ m g / (k v)`.
    pub fn slip_time(&self) -> Float {
        self.mu * self.m * self.g / (self.k * self.belt)
    }

    /// `(x, ẋ)` at `t`: riding the belt until [`Belt::slip_time`], then swinging about
    /// `μ m g / k` with amplitude `v / ω`.
    pub fn motion(&self, t: Float) -> [Float; 2] {
        let slip = self.slip_time();
        if t <= slip {
            return [self.belt * t, self.belt];
        }
        let omega = (self.k / self.m).sqrt();
        let centre = self.mu * self.m * self.g / self.k;
        let phase = omega * (t - slip);
        [
            centre + self.belt / omega * phase.sin(),
            self.belt * phase.cos(),
        ]
    }
}

/// Painlevé's rod: a uniform rod of mass `m` and length `2 l` (coordinates: its centre `x, y`
/// and its angle `θ` to the floor), its lower end `(x − l cos θ, y − l sin θ)` on a rough floor
/// (gap 1) and its upper end under a ceiling at `ceiling` (gap 0, open), friction `mu` at both.
/// Sliding with its lower end moving away from the centre (towards −x), the floor's push
/// `n M⁻¹ nᵀ − μ n M⁻¹ tᵀ = (1 + 3 cos²θ − 3 μ sin θ cos θ) / m` turns negative for
/// `μ > (1 + 3 cos²θ) / (3 sin θ cos θ)` (at least 4/3, at `tan θ = 2`): no consistent contact
/// force exists there, as Painlevé found (1895).
#[derive(Clone, Debug)]
pub struct PainleveRod {
    pub m: Float,
    pub l: Float,
    pub g: Float,
    pub mu: Float,
    pub ceiling: Float,
}

#[constrained_system]
impl PainleveRod {
    fn mass(&self) -> [Float; 3] {
        [self.m, self.m, self.m * self.l * self.l / 3.0]
    }

    fn force(&self) -> [Float; 3] {
        [0.0, -self.m * self.g, 0.0]
    }

    fn gaps(&self, [_x, y, th]: [Float; 3]) -> [Float; 2] {
        [self.ceiling - y - self.l * th.sin(), y - self.l * th.sin()]
    }

    fn slips(&self, [_x, _y, th]: [Float; 3], [vx, _vy, w]: [Float; 3]) -> [Float; 2] {
        [vx - self.l * th.sin() * w, vx + self.l * th.sin() * w]
    }

    fn friction(&self) -> [Float; 2] {
        [self.mu, self.mu]
    }
}

impl PainleveRod {
    /// The friction coefficient above which the rod at angle `th`, its lower end slipping
    /// towards −x, is in Painlevé's configuration: `(1 + 3 cos²θ) / (3 sin θ cos θ)`.
    pub fn threshold(th: Float) -> Float {
        let (sin, cos) = th.sin_cos();
        (1.0 + 3.0 * cos * cos) / (3.0 * sin * cos)
    }

    /// The rod at angle `th`, its lower end on the floor and slipping at `slip` along x.
    pub fn sliding(&self, th: Float, slip: Float) -> ([Float; 3], [Float; 3]) {
        ([0.0, self.l * th.sin(), th], [slip, 0.0, 0.0])
    }
}

/// A uniform disk of mass `m` and radius `r` (coordinates: its centre `x, y` and its angle `φ`,
/// counter-clockwise) over a rough floor (friction `mu`, restitution `e`): the oblique impact of
/// the textbooks, and rolling after it.
#[derive(Clone, Debug)]
pub struct Disk {
    pub m: Float,
    pub r: Float,
    pub g: Float,
    pub mu: Float,
    pub e: Float,
}

#[constrained_system]
impl Disk {
    fn mass(&self) -> [Float; 3] {
        [self.m, self.m, 0.5 * self.m * self.r * self.r]
    }

    fn force(&self) -> [Float; 3] {
        [0.0, -self.m * self.g, 0.0]
    }

    fn gaps(&self, [_x, y, _phi]: [Float; 3]) -> [Float; 1] {
        [y - self.r]
    }

    /// The velocity of the disk's lowest point along the floor.
    fn slips(&self, _q: [Float; 3], [vx, _vy, w]: [Float; 3]) -> [Float; 1] {
        [vx + self.r * w]
    }

    fn restitution(&self) -> [Float; 1] {
        [self.e]
    }

    fn friction(&self) -> [Float; 1] {
        [self.mu]
    }
}

impl Disk {
    /// `(ẋ, ẏ, φ̇)` right after the disk, not spinning, strikes the floor at `(vx, vy)`,
    /// `vx > 0 > vy`: the floor's impulse `P = m (1 + e) |vy|` and a tangential one `F` that
    /// takes `3 F / m` off the lowest point's slip `vx` (`F / m` off `ẋ`, `2 F / (m r)` off `φ̇`):
    /// `F = μ P` where that leaves it slipping, `F = m vx / 3` (rolling) where it does not.
    pub fn after_strike(&self, vx: Float, vy: Float) -> [Float; 3] {
        let normal = self.m * (1.0 + self.e) * -vy;
        let tangential = (self.mu * normal).min(self.m * vx / 3.0);
        [
            vx - tangential / self.m,
            -self.e * vy,
            -2.0 * tangential / (self.m * self.r),
        ]
    }
}

/// Two blocks of mass `m` on a rough floor (friction `mu`), joined by a spring of stiffness `k`
/// and rest length `rest`: two contacts that slip, and stick, at once. Released at rest
/// symmetrically, each block is a [`SlidingOscillator`] of stiffness `2 k` about its half of
/// the rest length.
#[derive(Clone, Debug)]
pub struct TwoBlocks {
    pub m: Float,
    pub g: Float,
    pub k: Float,
    pub mu: Float,
    pub rest: Float,
}

#[constrained_system]
impl TwoBlocks {
    fn mass(&self) -> [Float; 4] {
        [self.m, self.m, self.m, self.m]
    }

    fn force(&self, [x1, _y1, x2, _y2]: [Float; 4]) -> [Float; 4] {
        let pull = self.k * (x2 - x1 - self.rest);
        [pull, -self.m * self.g, -pull, -self.m * self.g]
    }

    fn gaps(&self, [_x1, y1, _x2, y2]: [Float; 4]) -> [Float; 2] {
        [y1, y2]
    }

    fn slips(&self, _q: [Float; 4], [vx1, _vy1, vx2, _vy2]: [Float; 4]) -> [Float; 2] {
        [vx1, vx2]
    }

    fn friction(&self) -> [Float; 2] {
        [self.mu, self.mu]
    }
}

impl TwoBlocks {
    /// Each block's motion about the centre, released at rest with the blocks `2 half_span`
    /// apart: the sliding oscillator it is.
    pub fn each_block(&self) -> SlidingOscillator {
        SlidingOscillator {
            m: self.m,
            g: self.g,
            k: 2.0 * self.k,
            mu: self.mu,
        }
    }
}
