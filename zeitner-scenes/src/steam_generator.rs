//! The paper's scene (eqs. 12–13): a steam generator on a pendulum column and a lateral strut.
//! q1, q2: horizontal and vertical displacement of the centre of mass; q3: rotation.

use zeitner::{constrained_system, Float, MultiplierModel, Options};

#[derive(Clone, Debug)]
pub struct SteamGenerator {
    /// Mass, kg.
    pub m: Float,
    /// Moment of inertia about the centre of mass, kg m².
    pub j: Float,
    /// Gravity, m/s².
    pub g: Float,
    /// Height of the load's line of action above the centre of mass, m.
    pub h1: Float,
    /// Length of the pendulum column, m.
    pub h2: Float,
    /// Lever arm of the lateral strut at C, m.
    pub h3: Float,
    /// Damper coefficient, N s/m.
    pub d: Float,
    /// Peak horizontal load, N.
    pub p0: Float,
    /// Rise time of the load, s.
    pub rise: Float,
    /// The load is switched off from this time on, s (infinite: never).
    pub off: Float,
}

impl SteamGenerator {
    /// The paper's defaults (SI units); the paper itself gives no figures.
    pub fn paper() -> Self {
        SteamGenerator {
            m: 4.0e5,
            j: 1.5e7,
            g: 9.81,
            h1: 4.0,
            h2: 6.0,
            h3: 8.0,
            d: 2.0e6,
            p0: 1.0e6,
            rise: 0.01,
            off: Float::INFINITY,
        }
    }

    /// The horizontal load P(t): a ramp to `p0` over the rise time, zero from `off` on.
    pub fn load(&self, t: Float) -> Float {
        if t < self.off {
            self.p0 * (t / self.rise).min(1.0)
        } else {
            0.0
        }
    }
}

/// The options of the firmware loop over this scene (`tests/on_target`) and of its host
/// reference (the example `firmware_reference`): RK4 at 1 ms, one step per 1 kHz tick, the
/// multipliers solved at every stage from the acceleration-level system. Well conditioned in
/// `f32` too: Newton on held multipliers finds them from the step end's positions, which in
/// `f32` fix them only to about `ε·2m/τ²`.
pub fn firmware_options() -> Options {
    Options {
        multipliers: MultiplierModel::EveryStage,
        ..Options::paper(1e-3)
    }
}

#[constrained_system]
impl SteamGenerator {
    fn mass(&self) -> [Float; 3] {
        [self.m, self.m, self.j]
    }

    fn force(
        &self,
        [_q1, _q2, _q3]: [Float; 3],
        [v1, _v2, _v3]: [Float; 3],
        t: Float,
    ) -> [Float; 3] {
        let p = self.load(t);
        [p - self.d * v1, -self.m * self.g, p * self.h1]
    }

    fn constraints(&self, [q1, q2, q3]: [Float; 3]) -> [Float; 2] {
        [
            q1 - self.h3 * q3,
            q1 * q1 + (q2 - self.h2).powi(2) - self.h2 * self.h2,
        ]
    }

    /// The load's kink at the end of its ramp and its switch-off: steps land on them.
    fn time_events(&self) -> [Float; 2] {
        [self.rise, self.off]
    }

    /// The supports' geometry and the damper, for sensitivities (the load's `p0` and `rise`
    /// are read in `load`, an opaque method, so they cannot be parameters).
    fn parameters(&self) -> [Float; 4] {
        [self.h3, self.h2, self.d, self.m]
    }
}

/// The paper's scene with a clearance at the lateral strut C: the strut engages only where
/// `|q1 - h3 q3|` reaches the clearance (a snubber with a gap on either side), and then acts
/// like the paper's strut; an impact with restitution `e` where it engages.
pub struct SteamGeneratorWithGap {
    pub base: SteamGenerator,
    /// The clearance on either side, m.
    pub clearance: Float,
    /// Newton's coefficient of restitution of the strut's contact.
    pub e: Float,
}

impl SteamGeneratorWithGap {
    /// The paper's scene with a 5 mm clearance and `e = 0.5`.
    pub fn paper() -> Self {
        SteamGeneratorWithGap {
            base: SteamGenerator::paper(),
            clearance: 0.005,
            e: 0.5,
        }
    }

    pub fn load(&self, t: Float) -> Float {
        self.base.load(t)
    }
}

#[constrained_system]
impl SteamGeneratorWithGap {
    fn mass(&self) -> [Float; 3] {
        [self.base.m, self.base.m, self.base.j]
    }

    fn force(
        &self,
        [_q1, _q2, _q3]: [Float; 3],
        [v1, _v2, _v3]: [Float; 3],
        t: Float,
    ) -> [Float; 3] {
        let p = self.load(t);
        [
            p - self.base.d * v1,
            -self.base.m * self.base.g,
            p * self.base.h1,
        ]
    }

    fn constraints(&self, [q1, q2, _q3]: [Float; 3]) -> [Float; 1] {
        [q1 * q1 + (q2 - self.base.h2).powi(2) - self.base.h2 * self.base.h2]
    }

    /// The strut's travel left before it engages, pushed (first) and pulled (second).
    fn gaps(&self, [q1, _q2, q3]: [Float; 3]) -> [Float; 2] {
        let travel = q1 - self.base.h3 * q3;
        [self.clearance - travel, self.clearance + travel]
    }

    fn restitution(&self) -> [Float; 2] {
        [self.e, self.e]
    }

    fn time_events(&self) -> [Float; 2] {
        [self.base.rise, self.base.off]
    }

    fn parameters(&self) -> [Float; 3] {
        [self.base.h3, self.clearance, self.base.d]
    }
}

/// The paper's steam generator whose lateral support at C is a slide bearing: C moves in a
/// guide with `clearance` on either side, strikes it (Newton's restitution `e`, no tangential
/// impulse), and then slides along it — vertically, the guide's direction — against Coulomb's
/// friction `mu`, or sticks. In the paper's linear geometry the rotation moves C across the guide
/// (`q1 − h3 q3`) and not along it, so C's slip velocity is `q2'`. The question the scene
/// answers for the support's design: how the friction of the plate changes the forces the
/// column and the support carry, and whether the support locks the structure.
#[derive(Clone, Debug)]
pub struct SlidingSupportSteamGenerator {
    pub base: SteamGenerator,
    /// The guide's clearance on either side of C, m.
    pub clearance: Float,
    /// Newton's coefficient of restitution where C strikes the guide.
    pub e: Float,
    /// Coulomb's coefficient of the guide's plates.
    pub mu: Float,
}

impl SlidingSupportSteamGenerator {
    /// The paper's scene with a 5 mm clearance, a plastic strike (`e = 0`) and steel on PTFE,
    /// `μ = 0.1`.
    pub fn paper() -> Self {
        SlidingSupportSteamGenerator {
            base: SteamGenerator::paper(),
            clearance: 0.005,
            e: 0.0,
            mu: 0.1,
        }
    }

    pub fn load(&self, t: Float) -> Float {
        self.base.load(t)
    }
}

#[constrained_system]
impl SlidingSupportSteamGenerator {
    fn mass(&self) -> [Float; 3] {
        [self.base.m, self.base.m, self.base.j]
    }

    fn force(
        &self,
        [_q1, _q2, _q3]: [Float; 3],
        [v1, _v2, _v3]: [Float; 3],
        t: Float,
    ) -> [Float; 3] {
        let p = self.load(t);
        [
            p - self.base.d * v1,
            -self.base.m * self.base.g,
            p * self.base.h1,
        ]
    }

    fn constraints(&self, [q1, q2, _q3]: [Float; 3]) -> [Float; 1] {
        [q1 * q1 + (q2 - self.base.h2).powi(2) - self.base.h2 * self.base.h2]
    }

    /// C's travel left before it meets the guide's plate, pushed (first) and pulled (second).
    fn gaps(&self, [q1, _q2, q3]: [Float; 3]) -> [Float; 2] {
        let travel = q1 - self.base.h3 * q3;
        [self.clearance - travel, self.clearance + travel]
    }

    /// C's velocity along the guide, on either plate.
    fn slips(&self, _q: [Float; 3], [_v1, v2, _v3]: [Float; 3]) -> [Float; 2] {
        [v2, v2]
    }

    fn restitution(&self) -> [Float; 2] {
        [self.e, self.e]
    }

    fn friction(&self) -> [Float; 2] {
        [self.mu, self.mu]
    }

    fn time_events(&self) -> [Float; 2] {
        [self.base.rise, self.base.off]
    }
}
