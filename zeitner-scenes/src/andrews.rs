//! Andrews' squeezing mechanism: 7 bodies, 7 angles, 6 constraints, a configuration-dependent
//! mass matrix (Hairer & Wanner II, sec. VII.7; the test set's problem `andrews`).
//! Coordinates q = (β, Θ, γ, Φ, δ, Ω, ε).

use zeitner::{constrained_system, Float};

/// The mechanism's parameters, named as in the test set.
#[derive(Clone, Copy, Debug)]
pub struct Andrews {
    pub m1: Float,
    pub m2: Float,
    pub m3: Float,
    pub m4: Float,
    pub m5: Float,
    pub m6: Float,
    pub m7: Float,
    pub i1: Float,
    pub i2: Float,
    pub i3: Float,
    pub i4: Float,
    pub i5: Float,
    pub i6: Float,
    pub i7: Float,
    pub xa: Float,
    pub ya: Float,
    pub xb: Float,
    pub yb: Float,
    pub xc: Float,
    pub yc: Float,
    pub c0: Float,
    pub l0: Float,
    pub mom: Float,
    pub d: Float,
    pub da: Float,
    pub e: Float,
    pub ea: Float,
    pub rr: Float,
    pub ra: Float,
    pub ss: Float,
    pub sa: Float,
    pub sb: Float,
    pub sc: Float,
    pub sd: Float,
    pub ta: Float,
    pub tb: Float,
    pub u: Float,
    pub ua: Float,
    pub ub: Float,
    pub zf: Float,
    pub zt: Float,
    pub fa: Float,
}

impl Andrews {
    /// The published parameters.
    pub fn published() -> Self {
        Andrews {
            m1: 0.04325,
            m2: 0.00365,
            m3: 0.02373,
            m4: 0.00706,
            m5: 0.07050,
            m6: 0.00706,
            m7: 0.05498,
            i1: 2.194e-6,
            i2: 4.410e-7,
            i3: 5.255e-6,
            i4: 5.667e-7,
            i5: 1.169e-5,
            i6: 5.667e-7,
            i7: 1.912e-5,
            xa: -0.06934,
            ya: -0.00227,
            xb: -0.03635,
            yb: 0.03273,
            xc: 0.014,
            yc: 0.072,
            c0: 4530.0,
            l0: 0.07785,
            mom: 0.033,
            d: 0.028,
            da: 0.0115,
            e: 0.02,
            ea: 0.01421,
            rr: 0.007,
            ra: 0.00092,
            ss: 0.035,
            sa: 0.01874,
            sb: 0.01043,
            sc: 0.018,
            sd: 0.02,
            ta: 0.02308,
            tb: 0.00916,
            u: 0.04,
            ua: 0.01228,
            ub: 0.00449,
            zf: 0.02,
            zt: 0.04,
            fa: 0.01421,
        }
    }

    /// The published consistent initial angles (velocities are zero), with all published digits.
    #[allow(clippy::excessive_precision)]
    pub const Q0: [Float; 7] = [
        -0.0617138900142764496358948458001,
        0.0,
        0.455279819163070380255912382449,
        0.222668390165885884674473185609,
        0.487364979543842550225598953530,
        -0.222668390165885884674473185609,
        1.23054744454982119249735015568,
    ];
}

#[constrained_system]
impl Andrews {
    fn mass(
        &self,
        [_beta, theta, _gamma, phi, _delta, omega, _epsilon]: [Float; 7],
    ) -> [[Float; 7]; 7] {
        let m2 = self.m2;
        let m4 = self.m4;
        let m6 = self.m6;
        let ee = self.e - self.ea;
        let zz = self.zf - self.fa;
        let m11 = self.m1 * self.ra * self.ra
            + m2 * (self.rr * self.rr - 2.0 * self.da * self.rr * theta.cos() + self.da * self.da)
            + self.i1
            + self.i2;
        let m12 = m2 * (self.da * self.da - self.da * self.rr * theta.cos()) + self.i2;
        let m22 = m2 * self.da * self.da + self.i2;
        let m33 = self.m3 * (self.sa * self.sa + self.sb * self.sb) + self.i3;
        let m44 = m4 * ee * ee + self.i4;
        let m45 = m4 * (ee * ee + self.zt * ee * phi.sin()) + self.i4;
        let m55 = m4 * (self.zt * self.zt + 2.0 * self.zt * ee * phi.sin() + ee * ee)
            + self.m5 * (self.ta * self.ta + self.tb * self.tb)
            + self.i4
            + self.i5;
        let m66 = m6 * zz * zz + self.i6;
        let m67 = m6 * (zz * zz - self.u * zz * omega.sin()) + self.i6;
        let m77 = m6 * (zz * zz - 2.0 * self.u * zz * omega.sin() + self.u * self.u)
            + self.m7 * (self.ua * self.ua + self.ub * self.ub)
            + self.i6
            + self.i7;
        [
            [m11, m12, 0.0, 0.0, 0.0, 0.0, 0.0],
            [m12, m22, 0.0, 0.0, 0.0, 0.0, 0.0],
            [0.0, 0.0, m33, 0.0, 0.0, 0.0, 0.0],
            [0.0, 0.0, 0.0, m44, m45, 0.0, 0.0],
            [0.0, 0.0, 0.0, m45, m55, 0.0, 0.0],
            [0.0, 0.0, 0.0, 0.0, 0.0, m66, m67],
            [0.0, 0.0, 0.0, 0.0, 0.0, m67, m77],
        ]
    }

    fn force(
        &self,
        [_beta, theta, gamma, phi, _delta, omega, _epsilon]: [Float; 7],
        [vbeta, vtheta, _vgamma, vphi, vdelta, vomega, vepsilon]: [Float; 7],
    ) -> [Float; 7] {
        let xd = self.sd * gamma.cos() + self.sc * gamma.sin() + self.xb;
        let yd = self.sd * gamma.sin() - self.sc * gamma.cos() + self.yb;
        let ls = ((xd - self.xc).powi(2) + (yd - self.yc).powi(2)).sqrt();
        let fs = -self.c0 * (ls - self.l0) / ls;
        let fx = fs * (xd - self.xc);
        let fy = fs * (yd - self.yc);
        let ee = self.e - self.ea;
        let zz = self.zf - self.fa;
        [
            self.mom - self.m2 * self.da * self.rr * vtheta * (vtheta + 2.0 * vbeta) * theta.sin(),
            self.m2 * self.da * self.rr * vbeta * vbeta * theta.sin(),
            fx * (self.sc * gamma.cos() - self.sd * gamma.sin())
                + fy * (self.sd * gamma.cos() + self.sc * gamma.sin()),
            self.m4 * self.zt * ee * vdelta * vdelta * phi.cos(),
            -self.m4 * self.zt * ee * vphi * (vphi + 2.0 * vdelta) * phi.cos(),
            -self.m6 * self.u * zz * vepsilon * vepsilon * omega.cos(),
            self.m6 * self.u * zz * vomega * (vomega + 2.0 * vepsilon) * omega.cos(),
        ]
    }

    fn constraints(
        &self,
        [beta, theta, gamma, phi, delta, omega, epsilon]: [Float; 7],
    ) -> [Float; 6] {
        let x = self.rr * beta.cos() - self.d * (beta + theta).cos();
        let y = self.rr * beta.sin() - self.d * (beta + theta).sin();
        [
            x - self.ss * gamma.sin() - self.xb,
            y + self.ss * gamma.cos() - self.yb,
            x - self.e * (phi + delta).sin() - self.zt * delta.cos() - self.xa,
            y + self.e * (phi + delta).cos() - self.zt * delta.sin() - self.ya,
            x - self.zf * (omega + epsilon).cos() - self.u * epsilon.sin() - self.xa,
            y - self.zf * (omega + epsilon).sin() + self.u * epsilon.cos() - self.ya,
        ]
    }

    /// For sensitivities: the driving torque, the spring, a mass and a rod length.
    fn parameters(&self) -> [Float; 4] {
        [self.mom, self.c0, self.m2, self.d]
    }
}

/// The published solution at t = 0.03 (test set, PSIDE at rtol = atol = 1e-14), reliable to
/// about 1e-9 relative in q, 1e-7 in q' and 1e-5 in λ.
#[allow(clippy::excessive_precision)]
pub fn published_end() -> super::reference::State<7, 6> {
    super::reference::State {
        q: [
            1.5810771196299040e+01,
            -1.5756371059842980e+01,
            4.0822240130731012e-02,
            -5.3473011632269485e-01,
            5.2440996588053035e-01,
            5.3473011632269485e-01,
            1.0480807410422630e+00,
        ],
        v: [
            1.1399203021512080e+03,
            -1.4243792949941110e+03,
            1.1032912219371340e+01,
            1.9293374644213849e+01,
            5.7356992847908084e-01,
            -1.9293374644213849e+01,
            3.2317916580269551e-01,
        ],
        lambda: [
            1.9917533337319099e+02,
            -2.9755312280150520e+01,
            2.3066541190983990e+01,
            3.1452713654759268e+01,
            2.2642492320827390e+01,
            1.1617407000196730e+01,
        ],
    }
}
