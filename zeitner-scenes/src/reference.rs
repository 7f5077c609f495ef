//! Independent references, derived by hand in reduced coordinates and integrated far below
//! any tolerance the tests use.

use super::contact::{Ball, WallPendulum};
use super::pendulum::Pendulum;
use super::spring_support::SpringSupportedPendulum;
use super::steam_generator::{SlidingSupportSteamGenerator, SteamGenerator, SteamGeneratorWithGap};
use zeitner::Float;

/// A reference state and its multipliers at one time.
pub struct State<const N: usize, const Z: usize> {
    pub q: [Float; N],
    pub v: [Float; N],
    pub lambda: [Float; Z],
}

fn phi_rhs(s: &SteamGenerator, t: Float, y: &[Float; 2]) -> [Float; 2] {
    let (phi, w) = (y[0], y[1]);
    let (sin, cos) = phi.sin_cos();
    let p = s.load(t);
    let mu = s.m * s.h2 * s.h2 + s.j * s.h2 * s.h2 * cos * cos / (s.h3 * s.h3);
    let q = (p - s.d * s.h2 * cos * w) * s.h2 * cos - s.m * s.g * s.h2 * sin
        + p * s.h1 * s.h2 * cos / s.h3;
    [
        w,
        (q + s.j * s.h2 * s.h2 * sin * cos * w * w / (s.h3 * s.h3)) / mu,
    ]
}

/// The steam generator has one degree of freedom; the derivation:
/// The scene has one degree of freedom. With the column angle φ,
///   q1 = h2 sin φ,  q2 = h2 (1 - cos φ),  q3 = q1 / h3,
/// both constraints hold identically. Kinetic energy:
///   T = ½ m (q1'² + q2'²) + ½ J q3'² = ½ μ(φ) φ'²,  μ(φ) = m h2² + J h2² cos²φ / h3².
/// Generalised force, F · ∂q/∂φ with F = (P - d q1', -m g, P h1):
///   Q = (P - d h2 cos φ φ') h2 cos φ - m g h2 sin φ + P h1 h2 cos φ / h3.
/// Lagrange's equation of the second kind, d/dt(μ φ') - ½ μ'(φ) φ'² = Q, with
/// μ'(φ) = -2 J h2² sin φ cos φ / h3², gives
///   φ'' = (Q + J h2² sin φ cos φ φ'² / h3²) / μ(φ).
/// The multipliers follow from the full equations: Gᵀλ = F - M q'', solved in least squares
/// (it is consistent), with G = [[1, 0, -h3], [2 q1, 2 (q2 - h2), 0]].
///
/// The steam generator's reduced-coordinate solution at `t`, integrated to about 1e-15.
pub fn steam_generator(s: &SteamGenerator, t: Float) -> State<3, 2> {
    // Integrate across the load's kink at t = rise in two pieces, 1e-5 s steps (RK4 error ~1e-15).
    let y = rk4(
        |t, y| phi_rhs(s, t, y),
        0.0,
        [0.0, 0.0],
        s.rise,
        (s.rise / 1e-5).round() as usize,
    );
    let y = rk4(
        |t, y| phi_rhs(s, t, y),
        s.rise,
        y,
        t,
        ((t - s.rise) / 1e-5).round() as usize,
    );
    let (phi, w) = (y[0], y[1]);
    let acc = phi_rhs(s, t, &y)[1];
    let (sin, cos) = phi.sin_cos();
    let q = [s.h2 * sin, s.h2 * (1.0 - cos), s.h2 * sin / s.h3];
    let v = [s.h2 * cos * w, s.h2 * sin * w, s.h2 * cos * w / s.h3];
    let a = [
        s.h2 * (cos * acc - sin * w * w),
        s.h2 * (sin * acc + cos * w * w),
        s.h2 * (cos * acc - sin * w * w) / s.h3,
    ];
    let p = s.load(t);
    let f = [p - s.d * v[0], -s.m * s.g, p * s.h1];
    let r = [f[0] - s.m * a[0], f[1] - s.m * a[1], f[2] - s.j * a[2]];
    let g = [[1.0, 0.0, -s.h3], [2.0 * q[0], 2.0 * (q[1] - s.h2), 0.0]];
    // Normal equations (G Gᵀ) λ = G r.
    let ggt = |i: usize, j: usize| (0..3).map(|k| g[i][k] * g[j][k]).sum::<Float>();
    let gr = |i: usize| (0..3).map(|k| g[i][k] * r[k]).sum::<Float>();
    let det = ggt(0, 0) * ggt(1, 1) - ggt(0, 1) * ggt(1, 0);
    let lambda = [
        (ggt(1, 1) * gr(0) - ggt(0, 1) * gr(1)) / det,
        (ggt(0, 0) * gr(1) - ggt(1, 0) * gr(0)) / det,
    ];
    State { q, v, lambda }
}

/// Classical RK4 for a first-order system `y' = f(t, y)` of `K` components, fixed step `h`,
/// from `t0` to `t1` (which `h` must divide). Used for reduced-coordinate references.
pub fn rk4<const K: usize>(
    f: impl Fn(Float, &[Float; K]) -> [Float; K],
    t0: Float,
    y0: [Float; K],
    t1: Float,
    steps: usize,
) -> [Float; K] {
    let h = (t1 - t0) / steps as Float;
    let mut y = y0;
    let axpy = |y: &[Float; K], a: Float, k: &[Float; K]| -> [Float; K] {
        core::array::from_fn(|i| y[i] + a * k[i])
    };
    for s in 0..steps {
        let t = t0 + s as Float * h;
        let k1 = f(t, &y);
        let k2 = f(t + h / 2.0, &axpy(&y, h / 2.0, &k1));
        let k3 = f(t + h / 2.0, &axpy(&y, h / 2.0, &k2));
        let k4 = f(t + h, &axpy(&y, h, &k3));
        y = core::array::from_fn(|i| y[i] + h / 6.0 * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i]));
    }
    y
}

/// The pendulum released horizontally at rest, from its angle ODE θ'' = -(g/L) sin θ
/// (θ from the downward vertical, x = L sin θ, y = -L cos θ), with λ from the radial balance
/// m L θ'² + m g cos θ = 2 L λ (G = (2x, 2y)). RK4 with steps of about 2e-5 s.
pub fn pendulum_released_horizontally(p: &Pendulum, t: Float) -> State<2, 1> {
    let (g, l, m) = (p.g, p.length, p.m);
    let steps = (t / 2e-5).round().max(1.0) as usize;
    let y = rk4(
        |_, y: &[Float; 2]| [y[1], -(g / l) * y[0].sin()],
        0.0,
        [zeitner::scalar::consts::FRAC_PI_2, 0.0],
        t,
        steps,
    );
    let (theta, w) = (y[0], y[1]);
    let (sin, cos) = theta.sin_cos();
    State {
        q: [l * sin, -l * cos],
        v: [l * w * cos, l * w * sin],
        lambda: [m * (l * w * w + g * cos) / (2.0 * l)],
    }
}

/// The pendulum beside an elastic wall (`e = 1`) released horizontally away from it: the free
/// pendulum mirrored at the wall (`x` and `x'` reflected where the free one has crossed), and no
/// force in the open gap.
pub fn wall_pendulum_released_horizontally(p: &WallPendulum, t: Float) -> State<2, 2> {
    let free = pendulum_released_horizontally(
        &Pendulum {
            m: p.m,
            length: p.length,
            g: p.g,
        },
        t,
    );
    let side = free.q[0].signum();
    State {
        q: [side * free.q[0], free.q[1]],
        v: [side * free.v[0], free.v[1]],
        lambda: [free.lambda[0], 0.0],
    }
}

/// The ball dropped at rest from `height` onto its floor, in closed form: it lands after
/// `t₁ = √(2 h / g)`; the `k`-th flight after it leaves at `u_k = eᵏ g t₁` and lasts `2 u_k / g`.
/// In flight the gap carries no force. For `e < 1` the flights sum to a finite time,
/// `t₁ (1 + e) / (1 - e)`, after which the ball rests on the floor, which carries its weight.
pub fn ball_dropped(ball: &Ball, height: Float, t: Float) -> State<1, 1> {
    let g = ball.g;
    let first = (2.0 * height / g).sqrt();
    if t <= first {
        return State {
            q: [height - 0.5 * g * t * t],
            v: [-g * t],
            lambda: [0.0],
        };
    }
    if ball.e < 1.0 && t >= first * (1.0 + ball.e) / (1.0 - ball.e) {
        // `M q'' = F - Gᵀλ` at rest with `G = 1`: `λ = -m g`, the floor's force `m g` upwards.
        return State {
            q: [0.0],
            v: [0.0],
            lambda: [-ball.m * g],
        };
    }
    let (mut leaves, mut speed) = (first, ball.e * g * first);
    // Before the rest time every flight ends before `t` runs out; the speed stays positive.
    while speed > 0.0 && t > leaves + 2.0 * speed / g {
        leaves += 2.0 * speed / g;
        speed *= ball.e;
    }
    let tau = t - leaves;
    State {
        q: [speed * tau - 0.5 * g * tau * tau],
        v: [speed - g * tau],
        lambda: [0.0],
    }
}

/// The spring-supported pendulum in reduced coordinates: the support `p = (x_s, y_s)` and the
/// rod angle `θ` from the downward vertical, bob `b = p + l (sin θ, -cos θ)`. Lagrange's
/// equations with `T = ½ m_s |p'|² + ½ m |p' + l θ' (cos θ, sin θ)|²`,
/// `V = ½ k |p|² + m_s g y_s + m g (y_s - l cos θ)` and the damping force `-c p'`:
///   (m_s + m) x_s'' + m l cos θ θ'' = -k x_s - c x_s' + m l θ'² sin θ,
///   (m_s + m) y_s'' + m l sin θ θ'' = -k y_s - c y_s' - (m_s + m) g - m l θ'² cos θ,
///   m l cos θ x_s'' + m l sin θ y_s'' + m l² θ'' = -m g l sin θ.
/// The multiplier from the bob's equation `m b'' = (0, -m g) - 2 (b - p) λ`.
/// RK4 with 2e-7 s steps (the support's frequency times the step is 0.02).
pub fn spring_supported_pendulum(s: &SpringSupportedPendulum, t: Float) -> State<4, 1> {
    let start = s.start();
    let y0 = [
        start[0],
        start[1],
        zeitner::scalar::consts::FRAC_PI_2,
        0.0,
        0.0,
        0.0,
    ];
    let steps = (t / 2e-7).round().max(1.0) as usize;
    let y = rk4(|_, y| spring_support_rhs(s, y), 0.0, y0, t, steps);
    let acc = spring_support_rhs(s, &y);
    let (sin, cos) = y[2].sin_cos();
    let (w, dw) = (y[5], acc[5]);
    let q = [y[0], y[1], y[0] + s.l * sin, y[1] - s.l * cos];
    let v = [y[3], y[4], y[3] + s.l * cos * w, y[4] + s.l * sin * w];
    let bob_acc = [
        acc[3] + s.l * (cos * dw - sin * w * w),
        acc[4] + s.l * (sin * dw + cos * w * w),
    ];
    let rod = [q[2] - q[0], q[3] - q[1]];
    let lambda =
        -(s.m * bob_acc[0] * rod[0] + (s.m * bob_acc[1] + s.m * s.g) * rod[1]) / (2.0 * s.l * s.l);
    State {
        q,
        v,
        lambda: [lambda],
    }
}

/// `(x_s, y_s, θ, x_s', y_s', θ')'` of the reduced equations above.
fn spring_support_rhs(s: &SpringSupportedPendulum, y: &[Float; 6]) -> [Float; 6] {
    let (sin, cos) = y[2].sin_cos();
    let (total, ml) = (s.support + s.m, s.m * s.l);
    let w = y[5];
    let mass = [
        [total, 0.0, ml * cos],
        [0.0, total, ml * sin],
        [ml * cos, ml * sin, ml * s.l],
    ];
    let rhs = [
        -s.k * y[0] - s.c * y[3] + ml * w * w * sin,
        -s.k * y[1] - s.c * y[4] - total * s.g - ml * w * w * cos,
        -s.m * s.g * s.l * sin,
    ];
    let a = solve3(mass, rhs);
    [y[3], y[4], y[5], a[0], a[1], a[2]]
}

/// `M x = b` for a 3×3 `M` by Cramer's rule.
fn solve3(m: [[Float; 3]; 3], b: [Float; 3]) -> [Float; 3] {
    let det = |m: &[[Float; 3]; 3]| {
        m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1])
            - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0])
            + m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0])
    };
    let d = det(&m);
    core::array::from_fn(|col| {
        let mut replaced = m;
        for row in 0..3 {
            replaced[row][col] = b[row];
        }
        det(&replaced) / d
    })
}

/// The steam generator with a clearance at its strut flies free until the strut engages: two
/// degrees of freedom, the column angle φ (q1 = h2 sin φ, q2 = h2 (1 - cos φ)) and the rotation
/// q3. `T = ½ m h2² φ'² + ½ J q3'²`, generalised forces
///   Q_φ = (P - d h2 cos φ φ') h2 cos φ - m g h2 sin φ,   Q_3 = P h1,
/// so `m h2² φ'' = Q_φ` and `J q3'' = P h1`. The strut engages where the travel
/// `|h2 sin φ - h3 q3|` reaches the clearance. RK4 with 1e-5 s steps across the load's kink, the
/// crossing refined by bisection on RK4 steps from the last grid point. Returns the time.
pub fn steam_generator_first_contact(s: &SteamGeneratorWithGap) -> Float {
    // The free flight ends within a few seconds under the sustained load.
    free_flight_to_contact(&s.base, s.clearance, 10.0).0
}

/// The free flight of [`steam_generator_first_contact`] until the travel at C reaches
/// `clearance` on either side, which it must before `before`: the time and
/// `(φ, φ', q3, q3')` then.
fn free_flight_to_contact(
    b: &SteamGenerator,
    clearance: Float,
    before: Float,
) -> (Float, [Float; 4]) {
    let rhs = |t: Float, y: &[Float; 4]| -> [Float; 4] {
        let (phi, w, _q3, w3) = (y[0], y[1], y[2], y[3]);
        let (sin, cos) = phi.sin_cos();
        let p = b.load(t);
        let q_phi = (p - b.d * b.h2 * cos * w) * b.h2 * cos - b.m * b.g * b.h2 * sin;
        [w, q_phi / (b.m * b.h2 * b.h2), w3, p * b.h1 / b.j]
    };
    let travel = |y: &[Float; 4]| (b.h2 * y[0].sin() - b.h3 * y[2]).abs();
    let h = 1e-5;
    // Up to the kink, then on in steps of h until the travel passes the clearance.
    let mut y = rk4(rhs, 0.0, [0.0; 4], b.rise, (b.rise / h).round() as usize);
    let mut t = b.rise;
    assert!(travel(&y) < clearance, "contact before the load's kink");
    loop {
        let next = rk4(rhs, t, y, t + h, 1);
        if travel(&next) >= clearance {
            break;
        }
        assert!(t + h < before, "no contact before {before}");
        (t, y) = (t + h, next);
    }
    let (mut lo, mut hi) = (0.0, h);
    for _ in 0..60 {
        let mid = 0.5 * (lo + hi);
        if travel(&rk4(rhs, t, y, t + mid, 1)) >= clearance {
            hi = mid;
        } else {
            lo = mid;
        }
    }
    let contact = t + 0.5 * (lo + hi);
    (contact, rk4(rhs, t, y, contact, 1))
}

/// The steam generator on its sliding support ([`SlidingSupportSteamGenerator`], plastic
/// strike `e = 0`) by Newton–Euler in reduced coordinates, phase by phase, to `t`:
/// - free flight in `(φ, q3)` as in [`steam_generator_first_contact`], until C's travel
///   `h2 sin φ − h3 q3` reaches the clearance on either side (bisection on RK4 steps);
/// - the strike: both constraints' velocities brought to zero (Newton's law with `e = 0`) by
///   the column's impulse, the plate's push `P` and Coulomb's `μP` against C's slip along the
///   guide where that leaves it slipping; where it does not, all three velocities brought to
///   zero (the three rows are independent), and the body then held at rest while the cone
///   holds its forces, or slipping from rest against the force the cone could not hold;
/// - slipping along the guide: one degree of freedom φ (`q1 = h2 sin φ`,
///   `q2 = h2 (1 − cos φ)`, `q3 = (q1 ∓ c)/h3`). The body's three equations
///   `M q'' = F − G_colᵀ λ + N n − μ σ N e₂`, with `q''` written through `φ''`, are linear in
///   `φ''`, the column's multiplier `λ` and the plate's push `N ≥ 0` along its normal `n`
///   (friction against the slip `q2'`, of sign `σ`); solved by Cramer's rule, RK4 at 1e-5 s.
///
/// Returns the state, then `[λ_column, N]`; panics where the slip stops or the plate lets go
/// before `t`, or the load changes while the body is held, which this reference does not model.
pub fn sliding_support_steam_generator(s: &SlidingSupportSteamGenerator, t: Float) -> State<3, 2> {
    assert!(s.e == 0.0, "the reference models a plastic strike");
    let b = &s.base;
    let h = 1e-5;
    let (strike, y) = free_flight_to_contact(b, s.clearance, t);
    // The plate struck: +1 pushed (gap 0, travel = +c), −1 pulled (gap 1, travel = −c).
    let side = (b.h2 * y[0].sin() - b.h3 * y[2]).signum();
    let (phi, w) = (y[0], y[1]);
    let (sin, cos) = phi.sin_cos();
    let q = [b.h2 * sin, b.h2 * (1.0 - cos), y[2]];
    let v = [b.h2 * cos * w, b.h2 * sin * w, y[3]];
    let mass = [b.m, b.m, b.j];
    // The column's row, the plate's normal (its push acts along it) and the guide's direction.
    let column = [2.0 * q[0], 2.0 * (q[1] - b.h2), 0.0];
    let normal = [-side, 0.0, side * b.h3];
    let along = [0.0, 1.0, 0.0];
    let dot = |a: &[Float; 3], c: &[Float; 3]| (0..3).map(|k| a[k] * c[k]).sum::<Float>();
    let weighted =
        |a: &[Float; 3], c: &[Float; 3]| (0..3).map(|k| a[k] * c[k] / mass[k]).sum::<Float>();
    // The strike slipping: `M Δv = −column Λ + P (normal − μσ along)`, with the column's and
    // the plate's rates zero after it; solved for (Λ, P).
    let sigma = (b.h2 * sin * w).signum();
    let pushing: [Float; 3] = core::array::from_fn(|k| normal[k] - s.mu * sigma * along[k]);
    let (a, c) = (weighted(&column, &column), weighted(&column, &pushing));
    let (d, e) = (weighted(&normal, &column), weighted(&normal, &pushing));
    let (r0, r1) = (dot(&column, &v), dot(&normal, &v));
    // −a Λ + c P = −r0, −d Λ + e P = −r1.
    let det = -a * e + c * d;
    let (column_impulse, push) = ((-r0 * e + c * r1) / det, (-a * -r1 - -d * -r0) / det);
    let slid: [Float; 3] = core::array::from_fn(|k| {
        v[k] + (-column[k] * column_impulse + push * pushing[k]) / mass[k]
    });
    let (mut w, mut sigma) = (slid[0] / (b.h2 * cos), sigma);
    let slips_on = sigma * slid[1] > 0.0;
    // Slipping along the guide: φ'' and the forces from the body's three equations.
    let slipping = |t: Float, phi: Float, w: Float, sigma: Float| -> (Float, [Float; 2]) {
        let (sin, cos) = phi.sin_cos();
        let (q1, q2) = (b.h2 * sin, b.h2 * (1.0 - cos));
        let p = b.load(t);
        let f = [p - b.d * b.h2 * cos * w, -b.m * b.g, p * b.h1];
        // Columns: φ'', λ (enters as −G_colᵀ λ), N (enters as +N n − μσN e₂).
        let system = [
            [b.m * b.h2 * cos, 2.0 * q1, -normal[0]],
            [b.m * b.h2 * sin, 2.0 * (q2 - b.h2), s.mu * sigma],
            [b.j * b.h2 * cos / b.h3, 0.0, -normal[2]],
        ];
        let rhs = [
            f[0] + b.m * b.h2 * sin * w * w,
            f[1] - b.m * b.h2 * cos * w * w,
            f[2] + b.j * b.h2 * sin * w * w / b.h3,
        ];
        let [acc, lambda, push] = solve3(system, rhs);
        (acc, [lambda, push])
    };
    if !slips_on {
        // The friction stopped the slip: the three rows hold every velocity at zero, with an
        // impulse `M(0 − v) = −column Λ + P normal + T along` inside the cone.
        let columns = |a: &[Float; 3], c: &[Float; 3], e: &[Float; 3]| {
            [[a[0], c[0], e[0]], [a[1], c[1], e[1]], [a[2], c[2], e[2]]]
        };
        let minus_column = column.map(|x| -x);
        let momentum: [Float; 3] = core::array::from_fn(|k| -mass[k] * v[k]);
        let [_, push, tangential] = solve3(columns(&minus_column, &normal, &along), momentum);
        assert!(tangential.abs() <= s.mu * push, "the strike does not stick");
        // At rest: held, `F − column λ + N normal + T along = 0`, while the cone holds it.
        let p = b.load(strike);
        let f = [p, -b.m * b.g, p * b.h1];
        let held = solve3(columns(&minus_column, &normal, &along), f.map(|x| -x));
        if held[2].abs() <= s.mu * held[1] {
            assert!(
                strike > b.rise && b.off > t,
                "the load changes while it is held"
            );
            return State {
                q: [q[0], q[1], (q[0] - side * s.clearance) / b.h3],
                v: [0.0; 3],
                lambda: [held[0], held[1]],
            };
        }
        // It slips against the force that could not hold it.
        (w, sigma) = (0.0, -held[2].signum());
    }
    let rhs = |t: Float, y: &[Float; 2]| [y[1], slipping(t, y[0], y[1], sigma).0];
    let slip = |y: &[Float; 2]| b.h2 * y[0].sin() * y[1];
    let steps = ((t - strike) / h).ceil().max(1.0) as usize;
    let step = (t - strike) / steps as Float;
    let mut phase = [phi, w];
    for k in 0..steps {
        phase = rk4(
            rhs,
            strike + k as Float * step,
            phase,
            strike + (k + 1) as Float * step,
            1,
        );
        assert!(
            slip(&phase).signum() == sigma,
            "the slip stopped before {t}"
        );
    }
    let (phi, w) = (phase[0], phase[1]);
    let (_, forces) = slipping(t, phi, w, sigma);
    assert!(forces[1] >= 0.0, "the plate let go before {t}");
    let (sin, cos) = phi.sin_cos();
    let q1 = b.h2 * sin;
    State {
        q: [q1, b.h2 * (1.0 - cos), (q1 - side * s.clearance) / b.h3],
        v: [b.h2 * cos * w, b.h2 * sin * w, b.h2 * cos * w / b.h3],
        lambda: forces,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The closed form lands at zero height with the free fall's speed and leaves at `e` times
    /// it, once per flight, up to the next landing.
    #[test]
    fn the_dropped_ball_leaves_each_landing_at_e_times_its_speed() {
        let ball = Ball {
            m: 1.0,
            g: 9.81,
            e: 0.8,
        };
        let (height, delta) = (1.0, 1e-9);
        let mut landing = (2.0 * height / ball.g).sqrt();
        let mut speed = ball.g * landing;
        for _ in 0..3 {
            let before = ball_dropped(&ball, height, landing - delta);
            let after = ball_dropped(&ball, height, landing + delta);
            assert!(before.q[0].abs() < 1e-7 && after.q[0].abs() < 1e-7);
            assert!(
                (before.v[0] + speed).abs() < 1e-7,
                "{} {speed}",
                before.v[0]
            );
            assert!((after.v[0] - ball.e * speed).abs() < 1e-7, "{}", after.v[0]);
            speed *= ball.e;
            landing += 2.0 * speed / ball.g;
        }
        // At and after the rest time it lies on the floor, which carries its weight; a ball
        // that does not bounce rests from its first landing.
        let rest = (2.0 * height / ball.g).sqrt() * (1.0 + ball.e) / (1.0 - ball.e);
        let resting = ball_dropped(&ball, height, rest + 1.0);
        assert_eq!(
            (resting.q, resting.v, resting.lambda),
            ([0.0], [0.0], [-ball.g])
        );
        let dead = Ball { e: 0.0, ..ball };
        assert_eq!(ball_dropped(&dead, height, 1.0).v, [0.0]);
    }
}
