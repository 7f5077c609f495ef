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

/// A ball (a uniform sphere of radius `r`) on a rough floor `z ≥ 0` in space, with friction
/// `mu` and restitution `e`: Coulomb's cone a disc. Its coordinates are its centre `(x, y, z)`
/// and three angles whose rates are its angular velocity `ω` (a sphere's dynamics do not depend
/// on its orientation); its lowest point slips at `(ẋ - r ω_y, ẏ + r ω_x)`. Its tangential
/// mobility is the same in every direction, so a slip keeps its direction while friction stops
/// it: after `|ṡ₀| / (7/2 μ g)` it rolls.
#[derive(Clone, Debug)]
pub struct Ball {
    pub m: Float,
    pub r: Float,
    pub g: Float,
    pub mu: Float,
    pub e: Float,
}

#[constrained_system]
impl Ball {
    fn mass(&self) -> [Float; 6] {
        let inertia = 0.4 * self.m * self.r * self.r;
        [self.m, self.m, self.m, inertia, inertia, inertia]
    }

    fn force(&self) -> [Float; 6] {
        [0.0, 0.0, -self.m * self.g, 0.0, 0.0, 0.0]
    }

    fn gaps(&self, [_x, _y, z, _ax, _ay, _az]: [Float; 6]) -> [Float; 1] {
        [z - self.r]
    }

    fn slips(&self, _q: [Float; 6], [vx, vy, _vz, wx, wy, _wz]: [Float; 6]) -> [Float; 2] {
        [vx - self.r * wy, vy + self.r * wx]
    }

    fn friction(&self) -> [Float; 1] {
        [self.mu]
    }

    fn restitution(&self) -> [Float; 1] {
        [self.e]
    }
}

impl Ball {
    /// The ball on the floor at `t`, started there with velocity `v0` and angular velocity
    /// `w0`: its slip `ṡ₀` falls along its direction `u` at `7/2 μ g` until it rolls at
    /// [`Ball::rolls_at`]; meanwhile the centre decelerates by `μ g u` and the spin turns by
    /// `5/2 μ g / r (-u_y, u_x, 0)`. Returns the six velocities and the centre's `(x, y)` moved.
    pub fn on_the_floor(
        &self,
        v0: [Float; 3],
        w0: [Float; 3],
        t: Float,
    ) -> ([Float; 6], [Float; 2]) {
        let slip = [v0[0] - self.r * w0[1], v0[1] + self.r * w0[0]];
        let speed = slip[0].hypot(slip[1]);
        let u = [slip[0] / speed, slip[1] / speed];
        let s = t.min(self.rolls_at(v0, w0));
        let (a, turn) = (self.mu * self.g, 2.5 * self.mu * self.g / self.r);
        let v = [v0[0] - a * s * u[0], v0[1] - a * s * u[1]];
        let w = [w0[0] - turn * s * u[1], w0[1] + turn * s * u[0], w0[2]];
        // Decelerating until it rolls, then at the rolling velocity.
        let moved = [
            v0[0] * s - 0.5 * a * s * s * u[0] + v[0] * (t - s),
            v0[1] * s - 0.5 * a * s * s * u[1] + v[1] * (t - s),
        ];
        ([v[0], v[1], 0.0, w[0], w[1], w[2]], moved)
    }

    /// When the ball started on the floor with `v0`, `w0` rolls: `|ṡ₀| / (7/2 μ g)`.
    pub fn rolls_at(&self, v0: [Float; 3], w0: [Float; 3]) -> Float {
        let slip = [v0[0] - self.r * w0[1], v0[1] + self.r * w0[0]];
        slip[0].hypot(slip[1]) / (3.5 * self.mu * self.g)
    }

    /// The velocities just after the ball strikes the floor at `vz < 0` with velocity `v` and
    /// angular velocity `w`: Newton's `-e vz` normal, and Coulomb's impulse against the slip,
    /// which keeps its direction and falls by `7/2 μ (1 + e)|vz|` or stops (the ball rolls).
    pub fn after_strike(&self, v: [Float; 3], w: [Float; 3]) -> [Float; 6] {
        let slip = [v[0] - self.r * w[1], v[1] + self.r * w[0]];
        let speed = slip[0].hypot(slip[1]);
        let push = (1.0 + self.e) * -v[2];
        // The friction impulse per unit mass, along -u: at most μ push, at least what stops the
        // slip (the slip falls by 7/2 of it).
        let friction = (self.mu * push).min(speed / 3.5);
        let u = match speed > 0.0 {
            true => [slip[0] / speed, slip[1] / speed],
            false => [0.0, 0.0],
        };
        let turn = 2.5 * friction / self.r;
        [
            v[0] - friction * u[0],
            v[1] - friction * u[1],
            -self.e * v[2],
            w[0] - turn * u[1],
            w[1] + turn * u[0],
            w[2],
        ]
    }
}

/// A point mass on a plane in space inclined at `angle` (rising along `y`), with friction `mu`,
/// sent across the slope: gravity's pull down the slope turns its slip while friction opposes
/// it, so it slides on a curve. Its gap is the distance from the plane; its slip velocity the
/// speed across the slope (`x`) and up it. With `k = μ cot θ`, the speed and the angle `φ`
/// between the velocity and the way down the slope keep `v sin φ / tan^k(φ/2)` (Routh's
/// hodograph); for `k > 1` the mass stops, turned straight down the slope, and stays.
#[derive(Clone, Debug)]
pub struct SlopeAcross {
    pub m: Float,
    pub g: Float,
    pub angle: Float,
    pub mu: Float,
}

#[constrained_system]
impl SlopeAcross {
    fn mass(&self) -> [Float; 3] {
        [self.m, self.m, self.m]
    }

    fn force(&self) -> [Float; 3] {
        [0.0, 0.0, -self.m * self.g]
    }

    fn gaps(&self, [_x, y, z]: [Float; 3]) -> [Float; 1] {
        [z * self.angle.cos() - y * self.angle.sin()]
    }

    fn slips(&self, _q: [Float; 3], [vx, vy, vz]: [Float; 3]) -> [Float; 2] {
        [vx, vy * self.angle.cos() + vz * self.angle.sin()]
    }

    fn friction(&self) -> [Float; 1] {
        [self.mu]
    }
}

impl SlopeAcross {
    /// `k = μ cot θ`: friction over gravity's pull along the slope.
    pub fn ratio(&self) -> Float {
        self.mu / self.angle.tan()
    }

    /// Sent across the slope at `speed` from the origin, the mass at the half-angle tangent
    /// `w = tan(φ/2)` of its turn (`1` at the start, `0` where it stops): the time, and its
    /// displacement across and down the slope. From the hodograph `v = v₀ w^k (1 + w²)/(2w)`
    /// and `v φ' = -g sin θ sin φ`, each a closed-form integral in `w`.
    pub fn sent_across(&self, speed: Float, w: Float) -> (Float, Float, Float) {
        let (k, a) = (self.ratio(), self.g * self.angle.sin());
        // ∫_w^1 x^p (1 + x²) dx and ∫_w^1 x^p (1 - x²)(1 + x²) dx.
        let rise =
            |p: Float| (1.0 - w.powf(p + 1.0)) / (p + 1.0) + (1.0 - w.powf(p + 3.0)) / (p + 3.0);
        let fall =
            |p: Float| (1.0 - w.powf(p + 1.0)) / (p + 1.0) - (1.0 - w.powf(p + 5.0)) / (p + 5.0);
        let time = speed / (2.0 * a) * rise(k - 2.0);
        let across = speed * speed / (2.0 * a) * rise(2.0 * k - 2.0);
        let down = speed * speed / (4.0 * a) * fall(2.0 * k - 3.0);
        (time, across, down)
    }

    /// The speed at half-angle tangent `w`: `v₀ w^k (1 + w²) / (2w)`.
    pub fn speed_at(&self, speed: Float, w: Float) -> Float {
        speed * w.powf(self.ratio()) * (1.0 + w * w) / (2.0 * w)
    }
}

/// A block (a point mass) on a rough floor `z ≥ 0` in space, pulled by a horizontal force
/// growing as `rate · t` along `heading` (radians from `x`): it sticks until the pull reaches
/// `μ m g`, then slides along the pull, `m s'' = rate · t − μ m g`.
#[derive(Clone, Debug)]
pub struct PulledBlock {
    pub m: Float,
    pub g: Float,
    pub mu: Float,
    pub rate: Float,
    pub heading: Float,
}

#[constrained_system]
impl PulledBlock {
    fn mass(&self) -> [Float; 3] {
        [self.m, self.m, self.m]
    }

    fn force(&self, t: Float) -> [Float; 3] {
        let pull = self.rate * t;
        [
            pull * self.heading.cos(),
            pull * self.heading.sin(),
            -self.m * self.g,
        ]
    }

    fn gaps(&self, [_x, _y, z]: [Float; 3]) -> [Float; 1] {
        [z]
    }

    fn slips(&self, _q: [Float; 3], [vx, vy, _vz]: [Float; 3]) -> [Float; 2] {
        [vx, vy]
    }

    fn friction(&self) -> [Float; 1] {
        [self.mu]
    }
}

impl PulledBlock {
    /// When the pull reaches `μ m g` and the block starts to slide.
    pub fn breaks_away_at(&self) -> Float {
        self.mu * self.m * self.g / self.rate
    }

    /// How far the block has slid along the pull at `t`, and at what speed:
    /// `rate (t − t₁)³ / 6m` and `rate (t − t₁)² / 2m` after the break-away time `t₁`.
    pub fn slid(&self, t: Float) -> (Float, Float) {
        let after = (t - self.breaks_away_at()).max(0.0);
        let c = self.rate / self.m;
        (c * after * after * after / 6.0, c * after * after / 2.0)
    }
}

/// A ladder (a uniform rod of length `l`) standing on a rough floor (`y ≥ 0`, friction
/// `mu_floor`) and leaning on a rough wall (`x ≥ 0`, friction `mu_wall`), its coordinates its
/// centre and its angle `θ` to the floor; the foot to the right of the wall. Sticking at both
/// ends it is held statically indeterminately: four rows on three coordinates, the friction
/// forces one free parameter, and it stands wherever some choice keeps both in their cones,
/// `tan θ ≥ (1 − μ_f μ_w) / (2 μ_f)`. Below that angle both ends slip.
#[derive(Clone, Debug)]
pub struct Ladder {
    pub m: Float,
    pub l: Float,
    pub g: Float,
    pub mu_floor: Float,
    pub mu_wall: Float,
}

#[constrained_system]
impl Ladder {
    fn mass(&self) -> [Float; 3] {
        [self.m, self.m, self.m * self.l * self.l / 12.0]
    }

    fn force(&self) -> [Float; 3] {
        [0.0, -self.m * self.g, 0.0]
    }

    fn gaps(&self, [x, y, theta]: [Float; 3]) -> [Float; 2] {
        let half = 0.5 * self.l;
        [y - half * theta.sin(), x - half * theta.cos()]
    }

    fn slips(&self, [_x, _y, theta]: [Float; 3], [vx, vy, w]: [Float; 3]) -> [Float; 2] {
        let half = 0.5 * self.l;
        [vx - half * theta.sin() * w, vy + half * theta.cos() * w]
    }

    fn friction(&self) -> [Float; 2] {
        [self.mu_floor, self.mu_wall]
    }
}

impl Ladder {
    /// The ladder at angle `theta`, standing: its centre and angle.
    pub fn standing(&self, theta: Float) -> [Float; 3] {
        let half = 0.5 * self.l;
        [half * theta.cos(), half * theta.sin(), theta]
    }

    /// The least angle at which it stands: `tan θ = (1 − μ_f μ_w) / (2 μ_f)`.
    pub fn least_standing_angle(&self) -> Float {
        ((1.0 - self.mu_floor * self.mu_wall) / (2.0 * self.mu_floor)).atan()
    }

    /// Both ends slipping (the foot away from the wall, the top down it): `θ''` and the
    /// floor's and the wall's normal forces at `(θ, θ')`, from the rod's three equations,
    /// linear in them.
    pub fn sliding(&self, theta: Float, omega: Float) -> (Float, Float, Float) {
        let (m, half, g) = (self.m, 0.5 * self.l, self.g);
        let (sin, cos) = theta.sin_cos();
        let inertia = m * self.l * self.l / 12.0;
        let (mf, mw) = (self.mu_floor, self.mu_wall);
        // Unknowns (θ'', N_floor, N_wall). The centre (half cos θ, half sin θ):
        // m ẍ = -μ_f N_f + N_w, m ÿ = N_f + μ_w N_w − m g,
        // and θ turning clockwise (the ladder steeper as it grows), I θ'' = −τ with the
        // torque about the centre τ = half (cos θ − μ_f sin θ) N_f − half (μ_w cos θ + sin θ) N_w.
        let a = [
            [m * half * sin, -mf, 1.0],
            [-m * half * cos, 1.0, mw],
            [inertia, half * (cos - mf * sin), -half * (mw * cos + sin)],
        ];
        let b = [
            -m * half * cos * omega * omega,
            m * g - m * half * sin * omega * omega,
            0.0,
        ];
        let x = solve3(a, b);
        (x[0], x[1], x[2])
    }

    /// Released at rest at `theta0` below its least standing angle, both ends slipping: `(θ, θ')`
    /// at `t`, by RK4 on [`Ladder::sliding`] at `step`.
    pub fn released(&self, theta0: Float, t: Float, step: Float) -> (Float, Float) {
        let steps = (t / step).ceil().max(1.0) as usize;
        let h = t / steps as Float;
        let f = |(theta, omega): (Float, Float)| (omega, self.sliding(theta, omega).0);
        let mut y = (theta0, 0.0);
        for _ in 0..steps {
            let k1 = f(y);
            let k2 = f((y.0 + 0.5 * h * k1.0, y.1 + 0.5 * h * k1.1));
            let k3 = f((y.0 + 0.5 * h * k2.0, y.1 + 0.5 * h * k2.1));
            let k4 = f((y.0 + h * k3.0, y.1 + h * k3.1));
            y = (
                y.0 + h / 6.0 * (k1.0 + 2.0 * k2.0 + 2.0 * k3.0 + k4.0),
                y.1 + h / 6.0 * (k1.1 + 2.0 * k2.1 + 2.0 * k3.1 + k4.1),
            );
        }
        y
    }
}

/// `a x = b` for a 3×3 `a`, by Cramer's rule.
fn solve3(a: [[Float; 3]; 3], b: [Float; 3]) -> [Float; 3] {
    let det = |m: [[Float; 3]; 3]| {
        m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1])
            - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0])
            + m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0])
    };
    let d = det(a);
    let mut x = [0.0; 3];
    for (j, value) in x.iter_mut().enumerate() {
        let mut m = a;
        for i in 0..3 {
            m[i][j] = b[i];
        }
        *value = det(m) / d;
    }
    x
}
