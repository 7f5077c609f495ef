//! Dormand & Prince's 8(5,3) pair as Hairer's DOP853 runs it (Hairer, Nørsett & Wanner,
//! *Solving ODEs I*, 2nd ed., II.10; the coefficients of Hairer's `dop853.f`, as published).

// The coefficients keep the digits they are published with.
#![allow(clippy::excessive_precision)]

use super::continuous::{self, weighted, Extension};
use super::explicit::{patterned, row, Difference, Nonzeros, ProbeStates, StiffnessProbe, Tableau};
use crate::consistency::consistent_point;
use crate::error::StepError;
use crate::model::Model;
use crate::output::Point;
use crate::scalar::Float;
use crate::system::{ConstrainedSystem, Vector};

/// The weights of the eighth-order solution. `dop853.f`'s thirteenth stage, the solution's
/// slope, serves the next step (first same as last) and the dense output, not the estimates.
const B: [Float; 12] = row(&[
    (0, 5.42937341165687622380535766363e-2),
    (5, 4.45031289275240888144113950566),
    (6, 1.89151789931450038304281599044),
    (7, -5.8012039600105847814672114227),
    (8, 3.1116436695781989440891606237e-1),
    (9, -1.52160949662516078556178806805e-1),
    (10, 2.01365400804030348374776537501e-1),
    (11, 4.47106157277725905176885569043e-2),
]);

/// `b` less the third-order weights `bhh` of `dop853.f`.
const E3: [Float; 12] = {
    let mut e = B;
    e[0] -= 0.244094488188976377952755905512;
    e[8] -= 0.733846688281611857341361741547;
    e[11] -= 0.220588235294117647058823529412e-1;
    e
};

/// The pair's twelve stages.
pub(crate) const DOP853: Tableau<12> = patterned(Tableau {
    a: [
        [0.0; 12],
        row(&[(0, 5.26001519587677318785587544488e-2)]),
        row(&[
            (0, 1.97250569845378994544595329183e-2),
            (1, 5.91751709536136983633785987549e-2),
        ]),
        row(&[
            (0, 2.95875854768068491816892993775e-2),
            (2, 8.87627564304205475450678981324e-2),
        ]),
        row(&[
            (0, 2.41365134159266685502369798665e-1),
            (2, -8.84549479328286085344864962717e-1),
            (3, 9.24834003261792003115737966543e-1),
        ]),
        row(&[
            (0, 3.7037037037037037037037037037e-2),
            (3, 1.70828608729473871279604482173e-1),
            (4, 1.25467687566822425016691814123e-1),
        ]),
        row(&[
            (0, 3.7109375e-2),
            (3, 1.70252211019544039314978060272e-1),
            (4, 6.02165389804559606850219397283e-2),
            (5, -1.7578125e-2),
        ]),
        row(&[
            (0, 3.70920001185047927108779319836e-2),
            (3, 1.70383925712239993810214054705e-1),
            (4, 1.07262030446373284651809199168e-1),
            (5, -1.53194377486244017527936158236e-2),
            (6, 8.27378916381402288758473766002e-3),
        ]),
        row(&[
            (0, 6.24110958716075717114429577812e-1),
            (3, -3.36089262944694129406857109825),
            (4, -8.68219346841726006818189891453e-1),
            (5, 2.75920996994467083049415600797e1),
            (6, 2.01540675504778934086186788979e1),
            (7, -4.34898841810699588477366255144e1),
        ]),
        row(&[
            (0, 4.77662536438264365890433908527e-1),
            (3, -2.48811461997166764192642586468),
            (4, -5.90290826836842996371446475743e-1),
            (5, 2.12300514481811942347288949897e1),
            (6, 1.52792336328824235832596922938e1),
            (7, -3.32882109689848629194453265587e1),
            (8, -2.03312017085086261358222928593e-2),
        ]),
        row(&[
            (0, -9.3714243008598732571704021658e-1),
            (3, 5.18637242884406370830023853209),
            (4, 1.09143734899672957818500254654),
            (5, -8.14978701074692612513997267357),
            (6, -1.85200656599969598641566180701e1),
            (7, 2.27394870993505042818970056734e1),
            (8, 2.49360555267965238987089396762),
            (9, -3.0467644718982195003823669022),
        ]),
        row(&[
            (0, 2.27331014751653820792359768449),
            (3, -1.05344954667372501984066689879e1),
            (4, -2.00087205822486249909675718444),
            (5, -1.79589318631187989172765950534e1),
            (6, 2.79488845294199600508499808837e1),
            (7, -2.85899827713502369474065508674),
            (8, -8.87285693353062954433549289258),
            (9, 1.23605671757943030647266201528e1),
            (10, 6.43392746015763530355970484046e-1),
        ]),
    ],
    nonzeros: Nonzeros::NONE,
    probe_difference: Difference::NONE,
    b: B,
    c: [
        0.0,
        0.526001519587677318785587544488e-01,
        0.789002279381515978178381316732e-01,
        0.118350341907227396726757197510,
        0.281649658092772603273242802490,
        0.333333333333333333333333333333,
        0.25,
        0.307692307692307692307692307692,
        0.651282051282051282051282051282,
        0.6,
        0.857142857142857142857142857142,
        1.0,
    ],
    // The fifth-order estimate `er` of `dop853.f`.
    e: Some(row(&[
        (0, 0.1312004499419488073250102996e-1),
        (5, -0.1225156446376204440720569753e1),
        (6, -0.4957589496572501915214079952),
        (7, 0.1664377182454986536961530415e1),
        (8, -0.3503288487499736816886487290),
        (9, 0.3341791187130174790297318841),
        (10, 0.8192320648511571246570742613e-1),
        (11, -0.2235530786388629525884427845e-1),
    ])),
    e_low: Some(E3),
    order: 8,
    // The fifth-order estimate tempered by the third-order one is controlled as of order 7,
    // with DOP853's exponent 1/8.
    embedded_order: Some(7),
    // The last stage at `t + h` against the solution's slope, with `dop853.f`'s boundary.
    stiffness: Some(StiffnessProbe {
        states: ProbeStates::LastStageAndEnd,
        boundary: 6.1,
    }),
});

/// Slopes of the continuous extension: the step's twelve stages, the end point's (the next
/// step's first stage) and three extra stages.
const SLOPES: usize = 16;

/// The nodes of the extra stages (`dop853.f`'s `c14`, `c15`, `c16`).
const EXTRA_C: [Float; 3] = [0.1, 0.2, 0.777777777777777777777777777778];

/// The extra stages' coefficients on the slopes before them (`dop853.f`'s `a14j`, `a15j`,
/// `a16j`; index 12 is the end point's slope).
const EXTRA_A: [[Float; SLOPES]; 3] = [
    row(&[
        (0, 5.61675022830479523392909219681e-2),
        (6, 2.53500210216624811088794765333e-1),
        (7, -2.46239037470802489917441475441e-1),
        (8, -1.24191423263816360469010140626e-1),
        (9, 1.5329179827876569731206322685e-1),
        (10, 8.20105229563468988491666602057e-3),
        (11, 7.56789766054569976138603589584e-3),
        (12, -8.298e-3),
    ]),
    row(&[
        (0, 3.18346481635021405060768473261e-2),
        (5, 2.83009096723667755288322961402e-2),
        (6, 5.35419883074385676223797384372e-2),
        (7, -5.49237485713909884646569340306e-2),
        (10, -1.08347328697249322858509316994e-4),
        (11, 3.82571090835658412954920192323e-4),
        (12, -3.40465008687404560802977114492e-4),
        (13, 1.41312443674632500278074618366e-1),
    ]),
    row(&[
        (0, -4.28896301583791923408573538692e-1),
        (5, -4.69762141536116384314449447206),
        (6, 7.68342119606259904184240953878),
        (7, 4.06898981839711007970213554331),
        (8, 3.56727187455281109270669543021e-1),
        (12, -1.39902416515901462129418009734e-3),
        (13, 2.9475147891527723389556272149),
        (14, -9.15095847217987001081870187138),
    ]),
];

/// The dense output's higher coefficients on the slopes (`dop853.f`'s `d4j` … `d7j`).
const DENSE_D: [[Float; SLOPES]; 4] = [
    row(&[
        (0, -0.84289382761090128651353491142e+01),
        (5, 0.56671495351937776962531783590),
        (6, -0.30689499459498916912797304727e+01),
        (7, 0.23846676565120698287728149680e+01),
        (8, 0.21170345824450282767155149946e+01),
        (9, -0.87139158377797299206789907490),
        (10, 0.22404374302607882758541771650e+01),
        (11, 0.63157877876946881815570249290),
        (12, -0.88990336451333310820698117400e-01),
        (13, 0.18148505520854727256656404962e+02),
        (14, -0.91946323924783554000451984436e+01),
        (15, -0.44360363875948939664310572000e+01),
    ]),
    row(&[
        (0, 0.10427508642579134603413151009e+02),
        (5, 0.24228349177525818288430175319e+03),
        (6, 0.16520045171727028198505394887e+03),
        (7, -0.37454675472269020279518312152e+03),
        (8, -0.22113666853125306036270938578e+02),
        (9, 0.77334326684722638389603898808e+01),
        (10, -0.30674084731089398182061213626e+02),
        (11, -0.93321305264302278729567221706e+01),
        (12, 0.15697238121770843886131091075e+02),
        (13, -0.31139403219565177677282850411e+02),
        (14, -0.93529243588444783865713862664e+01),
        (15, 0.35816841486394083752465898540e+02),
    ]),
    row(&[
        (0, 0.19985053242002433820987653617e+02),
        (5, -0.38703730874935176555105901742e+03),
        (6, -0.18917813819516756882830838328e+03),
        (7, 0.52780815920542364900561016686e+03),
        (8, -0.11573902539959630126141871134e+02),
        (9, 0.68812326946963000169666922661e+01),
        (10, -0.10006050966910838403183860980e+01),
        (11, 0.77771377980534432092869265740),
        (12, -0.27782057523535084065932004339e+01),
        (13, -0.60196695231264120758267380846e+02),
        (14, 0.84320405506677161018159903784e+02),
        (15, 0.11992291136182789328035130030e+02),
    ]),
    row(&[
        (0, -0.25693933462703749003312586129e+02),
        (5, -0.15418974869023643374053993627e+03),
        (6, -0.23152937917604549567536039109e+03),
        (7, 0.35763911791061412378285349910e+03),
        (8, 0.93405324183624310003907691704e+02),
        (9, -0.37458323136451633156875139351e+02),
        (10, 0.10409964950896230045147246184e+03),
        (11, 0.29840293426660503123344363579e+02),
        (12, -0.43533456590011143754432175058e+02),
        (13, 0.96324553959188282948394950600e+02),
        (14, -0.39177261675615439165231486172e+02),
        (15, -0.14972683625798562581422125276e+03),
    ]),
];

/// DOP853's continuous extension of order 7 (Hairer, Nørsett & Wanner, *Solving ODEs I*, II.6,
/// as `dop853.f`'s `contd8`): three more stages and a polynomial in `s`, closed by the step's
/// own end point (its end and its slope), so that it meets the projected end.
pub(crate) struct Dense;

/// The last step DOP853 integrated with the multipliers at every stage.
pub(crate) type Continuous<const N: usize> = continuous::Continuous<N, 12, Dense>;

impl<const N: usize> Extension<N, 12> for Dense {
    type Polynomial = [(Vector<N>, Vector<N>); 8];

    fn polynomial<S: ConstrainedSystem<N, Z>, const Z: usize>(
        model: &mut Model<'_, S, N, Z>,
        start: (Float, Vector<N>, Vector<N>, Float),
        slopes: &([Vector<N>; 12], [Vector<N>; 12]),
        end: &Point<N, Z>,
    ) -> Result<Self::Polynomial, StepError> {
        coefficients_for(model, start, slopes, end)
    }

    fn evaluate(c: &Self::Polynomial, s: Float) -> (Vector<N>, Vector<N>) {
        let s1 = 1.0 - s;
        // `r₁ + s(r₂ + s₁(r₃ + s(r₄ + s₁(r₅ + s(r₆ + s₁(r₇ + s r₈))))))`.
        let mut q = c[7].0;
        let mut v = c[7].1;
        for (k, (cq, cv)) in c.iter().enumerate().take(7).rev() {
            let w = if k % 2 == 0 { s } else { s1 };
            q = cq + w * q;
            v = cv + w * v;
        }
        (q, v)
    }
}

/// `dop853.f`'s `rcont1` … `rcont8` for the step from `(t₀, q₀, q₀')` of size `h` with the stage
/// slopes `slopes` to `end`, the three extra stages solved at every stage like the step's own.
fn coefficients_for<S: ConstrainedSystem<N, Z>, const N: usize, const Z: usize>(
    model: &mut Model<'_, S, N, Z>,
    (t0, q0, v0, h): (Float, Vector<N>, Vector<N>, Float),
    slopes: &([Vector<N>; 12], [Vector<N>; 12]),
    end: &Point<N, Z>,
) -> Result<[(Vector<N>, Vector<N>); 8], StepError> {
    let mut kq = [Vector::<N>::zeros(); SLOPES];
    let mut kv = [Vector::<N>::zeros(); SLOPES];
    kq[..12].copy_from_slice(&slopes.0);
    kv[..12].copy_from_slice(&slopes.1);
    (kq[12], kv[12]) = (end.v, end.a);
    for (i, (c, a)) in EXTRA_C.iter().zip(&EXTRA_A).enumerate() {
        let (q, v) = weighted((q0, v0), h, a, (&kq, &kv));
        kq[13 + i] = v;
        kv[13 + i] = consistent_point(model, t0 + c * h, q, v)?.a;
    }
    let (dq, dv) = (end.q - q0, end.v - v0);
    let (bq, bv) = (h * kq[0] - dq, h * kv[0] - dv);
    let zero = (Vector::zeros(), Vector::zeros());
    let [d4, d5, d6, d7] = DENSE_D.map(|d| weighted(zero, h, &d, (&kq, &kv)));
    Ok([
        (q0, v0),
        (dq, dv),
        (bq, bv),
        (dq - h * kq[12] - bq, dv - h * kv[12] - bv),
        d4,
        d5,
        d6,
        d7,
    ])
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::method::explicit::index1_stages;
    use crate::scalar::Lm;
    use crate::testing::{swinging, PENDULUM};

    /// One DOP853 step of size `h` from the swinging pendulum with the multipliers at every
    /// stage: its end made consistent, and its continuous extension's coefficients.
    fn step_and_extension(h: Float) -> (Point<2, 1>, [(Vector<2>, Vector<2>); 8]) {
        let mut model = Model::new(&PENDULUM).unwrap();
        let (q0, v0) = swinging();
        let mut slopes = ([Vector::<2>::zeros(); 12], [Vector::<2>::zeros(); 12]);
        let mut lambdas = [Vector::<1>::zeros(); 12];
        let into = (&mut slopes, &mut lambdas);
        let end =
            index1_stages(&mut model, &DOP853, (0.0, &q0, &v0), h, (None, false), into).unwrap();
        let end = consistent_point(&mut model, h, end.q, end.v).unwrap();
        let c = coefficients_for(&mut model, (0.0, q0, v0, h), &slopes, &end).unwrap();
        (end, c)
    }

    fn at(c: &[(Vector<2>, Vector<2>); 8], s: Float) -> (Vector<2>, Vector<2>) {
        <Dense as Extension<2, 12>>::evaluate(c, s)
    }

    #[test]
    fn the_extension_meets_both_ends_of_its_step() {
        let (end, c) = step_and_extension(0.1);
        assert_eq!(at(&c, 0.0), swinging());
        let (q, v) = at(&c, 1.0);
        assert!((q - end.q).amax() < 1e-15 && (v - end.v).amax() < 1e-15);
    }

    #[test]
    fn the_extension_is_of_order_seven() {
        // Within the step its local error is O(h⁸); the reference, a step of DOP853 itself to
        // the same time, errs by O(h⁹).
        let error = |h: Float| {
            let s = 0.37;
            let (q, v) = at(&step_and_extension(h).1, s);
            let (reference, _) = step_and_extension(s * h);
            (q - reference.q).amax().max((v - reference.v).amax())
        };
        // From h = 0.1 on the ratio is 2⁸ to 1 % (0.4 to 0.2 is still short of it: 2⁶·⁹).
        let (coarse, fine) = (error(0.1), error(0.05));
        let order = Lm::log2(coarse / fine) - 1.0;
        assert!(fine > 1e-13, "{fine}: at the rounding, no order to see");
        assert!(
            (order - 7.0).abs() < 0.5,
            "order {order} ({coarse:e}, {fine:e})"
        );
    }
}
