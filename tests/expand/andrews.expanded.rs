#[allow(dead_code)]
impl Andrews {
    fn mass(
        &self,
        [_beta,
        theta,
        _gamma,
        phi,
        _delta,
        omega,
        _epsilon,
        ]: [Float; 7],
    ) -> [[Float; 7]; 7] {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let m2 = self.m2;
        let m4 = self.m4;
        let m6 = self.m6;
        let ee = self.e - self.ea;
        let zz = self.zf - self.fa;
        let m11 = self.m1 * self.ra * self.ra
            + m2
                * (self.rr * self.rr - 2.0 * self.da * self.rr * theta.cos()
                    + self.da * self.da) + self.i1 + self.i2;
        let m12 = m2 * (self.da * self.da - self.da * self.rr * theta.cos()) + self.i2;
        let m22 = m2 * self.da * self.da + self.i2;
        let m33 = self.m3 * (self.sa * self.sa + self.sb * self.sb) + self.i3;
        let m44 = m4 * ee * ee + self.i4;
        let m45 = m4 * (ee * ee + self.zt * ee * phi.sin()) + self.i4;
        let m55 = m4 * (self.zt * self.zt + 2.0 * self.zt * ee * phi.sin() + ee * ee)
            + self.m5 * (self.ta * self.ta + self.tb * self.tb) + self.i4 + self.i5;
        let m66 = m6 * zz * zz + self.i6;
        let m67 = m6 * (zz * zz - self.u * zz * omega.sin()) + self.i6;
        let m77 = m6 * (zz * zz - 2.0 * self.u * zz * omega.sin() + self.u * self.u)
            + self.m7 * (self.ua * self.ua + self.ub * self.ub) + self.i6 + self.i7;
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
        [_beta,
        theta,
        gamma,
        phi,
        _delta,
        omega,
        _epsilon,
        ]: [Float; 7],
        [vbeta,
        vtheta,
        _vgamma,
        vphi,
        vdelta,
        vomega,
        vepsilon,
        ]: [Float; 7],
    ) -> [Float; 7] {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let xd = self.sd * gamma.cos() + self.sc * gamma.sin() + self.xb;
        let yd = self.sd * gamma.sin() - self.sc * gamma.cos() + self.yb;
        let ls = ((xd - self.xc).powi(2) + (yd - self.yc).powi(2)).sqrt();
        let fs = -self.c0 * (ls - self.l0) / ls;
        let fx = fs * (xd - self.xc);
        let fy = fs * (yd - self.yc);
        let ee = self.e - self.ea;
        let zz = self.zf - self.fa;
        [
            self.mom
                - self.m2 * self.da * self.rr * vtheta * (vtheta + 2.0 * vbeta)
                    * theta.sin(),
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
        [beta,
        theta,
        gamma,
        phi,
        delta,
        omega,
        epsilon,
        ]: [Float; 7],
    ) -> [Float; 6] {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
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
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        [self.mom, self.c0, self.m2, self.d]
    }
}
#[allow(unused_variables, unused_mut, clippy::all)]
impl ::zeitner::__private::ConstrainedSystem<7, 6> for Andrews {
    const POSITION_CONSTRAINTS: usize = 6;
    const MASS_IS_CONSTANT: bool = false;
    const DYNAMICS_DEPEND_ON_VELOCITY: bool = true;
    const SUMMARY: ::zeitner::__private::SceneSummary = ::zeitner::__private::SceneSummary {
        coordinates: 7,
        position_constraints: 6,
        velocity_constraints: 0,
        mass: ::zeitner::__private::MassKind::Full,
        time_dependent: false,
        functions: &[
            ::zeitner::__private::FunctionSummary {
                name: "mass_matrix",
                blocks: &[
                    ::zeitner::__private::BlockSummary {
                        name: "m",
                        rows: 7,
                        cols: 7,
                        nonzeros: &[
                            (0, 0),
                            (0, 1),
                            (1, 0),
                            (1, 1),
                            (2, 2),
                            (3, 3),
                            (3, 4),
                            (4, 3),
                            (4, 4),
                            (5, 5),
                            (5, 6),
                            (6, 5),
                            (6, 6),
                        ],
                    },
                ],
                ops: ::zeitner::__private::OpCounts {
                    adds: 30u64,
                    muls: 44u64,
                    divs: 0u64,
                    transcendental: 3u64,
                    opaque_calls: 0u64,
                },
                ops_unshared: ::zeitner::__private::OpCounts {
                    adds: 50u64,
                    muls: 59u64,
                    divs: 0u64,
                    transcendental: 9u64,
                    opaque_calls: 0u64,
                },
            },
            ::zeitner::__private::FunctionSummary {
                name: "applied_force",
                blocks: &[
                    ::zeitner::__private::BlockSummary {
                        name: "f",
                        rows: 7,
                        cols: 1,
                        nonzeros: &[
                            (0, 0),
                            (1, 0),
                            (2, 0),
                            (3, 0),
                            (4, 0),
                            (5, 0),
                            (6, 0),
                        ],
                    },
                ],
                ops: ::zeitner::__private::OpCounts {
                    adds: 19u64,
                    muls: 38u64,
                    divs: 1u64,
                    transcendental: 6u64,
                    opaque_calls: 0u64,
                },
                ops_unshared: ::zeitner::__private::OpCounts {
                    adds: 50u64,
                    muls: 71u64,
                    divs: 2u64,
                    transcendental: 34u64,
                    opaque_calls: 0u64,
                },
            },
            ::zeitner::__private::FunctionSummary {
                name: "constraint_residual",
                blocks: &[
                    ::zeitner::__private::BlockSummary {
                        name: "g",
                        rows: 6,
                        cols: 1,
                        nonzeros: &[(0, 0), (1, 0), (2, 0), (3, 0), (4, 0), (5, 0)],
                    },
                ],
                ops: ::zeitner::__private::OpCounts {
                    adds: 21u64,
                    muls: 14u64,
                    divs: 0u64,
                    transcendental: 14u64,
                    opaque_calls: 0u64,
                },
                ops_unshared: ::zeitner::__private::OpCounts {
                    adds: 32u64,
                    muls: 22u64,
                    divs: 0u64,
                    transcendental: 22u64,
                    opaque_calls: 0u64,
                },
            },
            ::zeitner::__private::FunctionSummary {
                name: "constraint_jacobian",
                blocks: &[
                    ::zeitner::__private::BlockSummary {
                        name: "g",
                        rows: 6,
                        cols: 7,
                        nonzeros: &[
                            (0, 0),
                            (0, 1),
                            (0, 2),
                            (1, 0),
                            (1, 1),
                            (1, 2),
                            (2, 0),
                            (2, 1),
                            (2, 3),
                            (2, 4),
                            (3, 0),
                            (3, 1),
                            (3, 3),
                            (3, 4),
                            (4, 0),
                            (4, 1),
                            (4, 5),
                            (4, 6),
                            (5, 0),
                            (5, 1),
                            (5, 5),
                            (5, 6),
                        ],
                    },
                ],
                ops: ::zeitner::__private::OpCounts {
                    adds: 15u64,
                    muls: 14u64,
                    divs: 0u64,
                    transcendental: 14u64,
                    opaque_calls: 0u64,
                },
                ops_unshared: ::zeitner::__private::OpCounts {
                    adds: 40u64,
                    muls: 32u64,
                    divs: 0u64,
                    transcendental: 32u64,
                    opaque_calls: 0u64,
                },
            },
            ::zeitner::__private::FunctionSummary {
                name: "constraint_rate",
                blocks: &[
                    ::zeitner::__private::BlockSummary {
                        name: "w",
                        rows: 6,
                        cols: 1,
                        nonzeros: &[(0, 0), (1, 0), (2, 0), (3, 0), (4, 0), (5, 0)],
                    },
                ],
                ops: ::zeitner::__private::OpCounts {
                    adds: 23u64,
                    muls: 28u64,
                    divs: 0u64,
                    transcendental: 14u64,
                    opaque_calls: 0u64,
                },
                ops_unshared: ::zeitner::__private::OpCounts {
                    adds: 48u64,
                    muls: 54u64,
                    divs: 0u64,
                    transcendental: 32u64,
                    opaque_calls: 0u64,
                },
            },
            ::zeitner::__private::FunctionSummary {
                name: "constraint_acceleration_bias",
                blocks: &[
                    ::zeitner::__private::BlockSummary {
                        name: "b",
                        rows: 6,
                        cols: 1,
                        nonzeros: &[(0, 0), (1, 0), (2, 0), (3, 0), (4, 0), (5, 0)],
                    },
                ],
                ops: ::zeitner::__private::OpCounts {
                    adds: 34u64,
                    muls: 48u64,
                    divs: 0u64,
                    transcendental: 14u64,
                    opaque_calls: 0u64,
                },
                ops_unshared: ::zeitner::__private::OpCounts {
                    adds: 87u64,
                    muls: 116u64,
                    divs: 0u64,
                    transcendental: 52u64,
                    opaque_calls: 0u64,
                },
            },
            ::zeitner::__private::FunctionSummary {
                name: "stage",
                blocks: &[
                    ::zeitner::__private::BlockSummary {
                        name: "m",
                        rows: 7,
                        cols: 7,
                        nonzeros: &[
                            (0, 0),
                            (0, 1),
                            (1, 0),
                            (1, 1),
                            (2, 2),
                            (3, 3),
                            (3, 4),
                            (4, 3),
                            (4, 4),
                            (5, 5),
                            (5, 6),
                            (6, 5),
                            (6, 6),
                        ],
                    },
                    ::zeitner::__private::BlockSummary {
                        name: "f",
                        rows: 7,
                        cols: 1,
                        nonzeros: &[
                            (0, 0),
                            (1, 0),
                            (2, 0),
                            (3, 0),
                            (4, 0),
                            (5, 0),
                            (6, 0),
                        ],
                    },
                    ::zeitner::__private::BlockSummary {
                        name: "g",
                        rows: 6,
                        cols: 7,
                        nonzeros: &[
                            (0, 0),
                            (0, 1),
                            (0, 2),
                            (1, 0),
                            (1, 1),
                            (1, 2),
                            (2, 0),
                            (2, 1),
                            (2, 3),
                            (2, 4),
                            (3, 0),
                            (3, 1),
                            (3, 3),
                            (3, 4),
                            (4, 0),
                            (4, 1),
                            (4, 5),
                            (4, 6),
                            (5, 0),
                            (5, 1),
                            (5, 5),
                            (5, 6),
                        ],
                    },
                    ::zeitner::__private::BlockSummary {
                        name: "b",
                        rows: 6,
                        cols: 1,
                        nonzeros: &[(0, 0), (1, 0), (2, 0), (3, 0), (4, 0), (5, 0)],
                    },
                ],
                ops: ::zeitner::__private::OpCounts {
                    adds: 90u64,
                    muls: 129u64,
                    divs: 1u64,
                    transcendental: 21u64,
                    opaque_calls: 0u64,
                },
                ops_unshared: ::zeitner::__private::OpCounts {
                    adds: 227u64,
                    muls: 278u64,
                    divs: 2u64,
                    transcendental: 127u64,
                    opaque_calls: 0u64,
                },
            },
            ::zeitner::__private::FunctionSummary {
                name: "force_jacobians",
                blocks: &[
                    ::zeitner::__private::BlockSummary {
                        name: "dq",
                        rows: 7,
                        cols: 7,
                        nonzeros: &[
                            (0, 1),
                            (1, 1),
                            (2, 2),
                            (3, 3),
                            (4, 3),
                            (5, 5),
                            (6, 5),
                        ],
                    },
                    ::zeitner::__private::BlockSummary {
                        name: "dv",
                        rows: 7,
                        cols: 7,
                        nonzeros: &[
                            (0, 0),
                            (0, 1),
                            (1, 0),
                            (3, 4),
                            (4, 3),
                            (4, 4),
                            (5, 6),
                            (6, 5),
                            (6, 6),
                        ],
                    },
                ],
                ops: ::zeitner::__private::OpCounts {
                    adds: 35u64,
                    muls: 70u64,
                    divs: 3u64,
                    transcendental: 9u64,
                    opaque_calls: 0u64,
                },
                ops_unshared: ::zeitner::__private::OpCounts {
                    adds: 224u64,
                    muls: 291u64,
                    divs: 12u64,
                    transcendental: 157u64,
                    opaque_calls: 0u64,
                },
            },
            ::zeitner::__private::FunctionSummary {
                name: "constraint_force_jacobians",
                blocks: &[
                    ::zeitner::__private::BlockSummary {
                        name: "dq",
                        rows: 7,
                        cols: 7,
                        nonzeros: &[
                            (0, 0),
                            (0, 1),
                            (1, 0),
                            (1, 1),
                            (2, 2),
                            (3, 3),
                            (3, 4),
                            (4, 3),
                            (4, 4),
                            (5, 5),
                            (5, 6),
                            (6, 5),
                            (6, 6),
                        ],
                    },
                    ::zeitner::__private::BlockSummary {
                        name: "dv",
                        rows: 7,
                        cols: 7,
                        nonzeros: &[],
                    },
                ],
                ops: ::zeitner::__private::OpCounts {
                    adds: 24u64,
                    muls: 36u64,
                    divs: 0u64,
                    transcendental: 14u64,
                    opaque_calls: 0u64,
                },
                ops_unshared: ::zeitner::__private::OpCounts {
                    adds: 79u64,
                    muls: 94u64,
                    divs: 0u64,
                    transcendental: 52u64,
                    opaque_calls: 0u64,
                },
            },
            ::zeitner::__private::FunctionSummary {
                name: "mass_jacobian_product",
                blocks: &[
                    ::zeitner::__private::BlockSummary {
                        name: "dq",
                        rows: 7,
                        cols: 7,
                        nonzeros: &[(0, 1), (1, 1), (3, 3), (4, 3), (5, 5), (6, 5)],
                    },
                ],
                ops: ::zeitner::__private::OpCounts {
                    adds: 7u64,
                    muls: 30u64,
                    divs: 0u64,
                    transcendental: 3u64,
                    opaque_calls: 0u64,
                },
                ops_unshared: ::zeitner::__private::OpCounts {
                    adds: 11u64,
                    muls: 39u64,
                    divs: 0u64,
                    transcendental: 9u64,
                    opaque_calls: 0u64,
                },
            },
            ::zeitner::__private::FunctionSummary {
                name: "rate_jacobians",
                blocks: &[
                    ::zeitner::__private::BlockSummary {
                        name: "wq",
                        rows: 6,
                        cols: 7,
                        nonzeros: &[
                            (0, 0),
                            (0, 1),
                            (0, 2),
                            (1, 0),
                            (1, 1),
                            (1, 2),
                            (2, 0),
                            (2, 1),
                            (2, 3),
                            (2, 4),
                            (3, 0),
                            (3, 1),
                            (3, 3),
                            (3, 4),
                            (4, 0),
                            (4, 1),
                            (4, 5),
                            (4, 6),
                            (5, 0),
                            (5, 1),
                            (5, 5),
                            (5, 6),
                        ],
                    },
                    ::zeitner::__private::BlockSummary {
                        name: "wv",
                        rows: 6,
                        cols: 7,
                        nonzeros: &[
                            (0, 0),
                            (0, 1),
                            (0, 2),
                            (1, 0),
                            (1, 1),
                            (1, 2),
                            (2, 0),
                            (2, 1),
                            (2, 3),
                            (2, 4),
                            (3, 0),
                            (3, 1),
                            (3, 3),
                            (3, 4),
                            (4, 0),
                            (4, 1),
                            (4, 5),
                            (4, 6),
                            (5, 0),
                            (5, 1),
                            (5, 5),
                            (5, 6),
                        ],
                    },
                ],
                ops: ::zeitner::__private::OpCounts {
                    adds: 32u64,
                    muls: 34u64,
                    divs: 0u64,
                    transcendental: 14u64,
                    opaque_calls: 0u64,
                },
                ops_unshared: ::zeitner::__private::OpCounts {
                    adds: 112u64,
                    muls: 126u64,
                    divs: 0u64,
                    transcendental: 84u64,
                    opaque_calls: 0u64,
                },
            },
            ::zeitner::__private::FunctionSummary {
                name: "acceleration_constraint_jacobians",
                blocks: &[
                    ::zeitner::__private::BlockSummary {
                        name: "cq",
                        rows: 6,
                        cols: 7,
                        nonzeros: &[
                            (0, 0),
                            (0, 1),
                            (0, 2),
                            (1, 0),
                            (1, 1),
                            (1, 2),
                            (2, 0),
                            (2, 1),
                            (2, 3),
                            (2, 4),
                            (3, 0),
                            (3, 1),
                            (3, 3),
                            (3, 4),
                            (4, 0),
                            (4, 1),
                            (4, 5),
                            (4, 6),
                            (5, 0),
                            (5, 1),
                            (5, 5),
                            (5, 6),
                        ],
                    },
                    ::zeitner::__private::BlockSummary {
                        name: "cv",
                        rows: 6,
                        cols: 7,
                        nonzeros: &[
                            (0, 0),
                            (0, 1),
                            (0, 2),
                            (1, 0),
                            (1, 1),
                            (1, 2),
                            (2, 0),
                            (2, 1),
                            (2, 3),
                            (2, 4),
                            (3, 0),
                            (3, 1),
                            (3, 3),
                            (3, 4),
                            (4, 0),
                            (4, 1),
                            (4, 5),
                            (4, 6),
                            (5, 0),
                            (5, 1),
                            (5, 5),
                            (5, 6),
                        ],
                    },
                    ::zeitner::__private::BlockSummary {
                        name: "cp",
                        rows: 6,
                        cols: 4,
                        nonzeros: &[(0, 3), (1, 3), (2, 3), (3, 3), (4, 3), (5, 3)],
                    },
                ],
                ops: ::zeitner::__private::OpCounts {
                    adds: 106u64,
                    muls: 91u64,
                    divs: 0u64,
                    transcendental: 14u64,
                    opaque_calls: 0u64,
                },
                ops_unshared: ::zeitner::__private::OpCounts {
                    adds: 482u64,
                    muls: 544u64,
                    divs: 0u64,
                    transcendental: 282u64,
                    opaque_calls: 0u64,
                },
            },
            ::zeitner::__private::FunctionSummary {
                name: "parameter_values",
                blocks: &[
                    ::zeitner::__private::BlockSummary {
                        name: "theta",
                        rows: 4,
                        cols: 1,
                        nonzeros: &[(0, 0), (1, 0), (2, 0), (3, 0)],
                    },
                ],
                ops: ::zeitner::__private::OpCounts {
                    adds: 0u64,
                    muls: 0u64,
                    divs: 0u64,
                    transcendental: 0u64,
                    opaque_calls: 0u64,
                },
                ops_unshared: ::zeitner::__private::OpCounts {
                    adds: 0u64,
                    muls: 0u64,
                    divs: 0u64,
                    transcendental: 0u64,
                    opaque_calls: 0u64,
                },
            },
            ::zeitner::__private::FunctionSummary {
                name: "parameter_force",
                blocks: &[
                    ::zeitner::__private::BlockSummary {
                        name: "df",
                        rows: 7,
                        cols: 4,
                        nonzeros: &[(0, 0), (0, 2), (0, 3), (1, 2), (1, 3), (2, 1)],
                    },
                ],
                ops: ::zeitner::__private::OpCounts {
                    adds: 26u64,
                    muls: 34u64,
                    divs: 1u64,
                    transcendental: 7u64,
                    opaque_calls: 0u64,
                },
                ops_unshared: ::zeitner::__private::OpCounts {
                    adds: 72u64,
                    muls: 73u64,
                    divs: 2u64,
                    transcendental: 45u64,
                    opaque_calls: 0u64,
                },
            },
            ::zeitner::__private::FunctionSummary {
                name: "parameter_constraints",
                blocks: &[
                    ::zeitner::__private::BlockSummary {
                        name: "dg",
                        rows: 6,
                        cols: 4,
                        nonzeros: &[(0, 3), (1, 3), (2, 3), (3, 3), (4, 3), (5, 3)],
                    },
                    ::zeitner::__private::BlockSummary {
                        name: "dw",
                        rows: 6,
                        cols: 4,
                        nonzeros: &[(0, 3), (1, 3), (2, 3), (3, 3), (4, 3), (5, 3)],
                    },
                ],
                ops: ::zeitner::__private::OpCounts {
                    adds: 6u64,
                    muls: 4u64,
                    divs: 0u64,
                    transcendental: 2u64,
                    opaque_calls: 0u64,
                },
                ops_unshared: ::zeitner::__private::OpCounts {
                    adds: 33u64,
                    muls: 12u64,
                    divs: 0u64,
                    transcendental: 18u64,
                    opaque_calls: 0u64,
                },
            },
        ],
    };
    type Mass = ::zeitner::__private::FullMass<7>;
    type Storage = ::zeitner::__private::Dense;
    const SPARSITY: ::core::option::Option<::zeitner::__private::Sparsity> = ::core::option::Option::Some(::zeitner::__private::Sparsity {
        constraint_jacobian: &[
            (0, 0),
            (0, 1),
            (0, 2),
            (1, 0),
            (1, 1),
            (1, 2),
            (2, 0),
            (2, 1),
            (2, 3),
            (2, 4),
            (3, 0),
            (3, 1),
            (3, 3),
            (3, 4),
            (4, 0),
            (4, 1),
            (4, 5),
            (4, 6),
            (5, 0),
            (5, 1),
            (5, 5),
            (5, 6),
        ],
        force_jacobians: [
            &[(0, 1), (1, 1), (2, 2), (3, 3), (4, 3), (5, 5), (6, 5)],
            &[(0, 0), (0, 1), (1, 0), (3, 4), (4, 3), (4, 4), (5, 6), (6, 5), (6, 6)],
        ],
        constraint_force_jacobians: [
            &[
                (0, 0),
                (0, 1),
                (1, 0),
                (1, 1),
                (2, 2),
                (3, 3),
                (3, 4),
                (4, 3),
                (4, 4),
                (5, 5),
                (5, 6),
                (6, 5),
                (6, 6),
            ],
            &[],
        ],
    });
    #[inline]
    fn mass_matrix(
        &self,
        q: &::zeitner::__private::Vector<7>,
        t: ::zeitner::__private::Float,
    ) -> Self::Mass {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let s0 = self.e - self.ea;
        let s1 = self.zf - self.fa;
        let s2 = q[1].cos();
        let s3 = self.da.powi(2);
        let s4 = self.i2 + self.m2 * (s3 - s2 * (self.rr * self.da));
        let s5 = s0.powi(2);
        let s6 = q[3].sin();
        let s7 = self.i4 + self.m4 * (s5 + s0 * self.zt * s6);
        let s8 = s1.powi(2);
        let s9 = q[5].sin();
        let s10 = self.i6 + self.m6 * (s8 - s1 * self.u * s9);
        let mut m = ::zeitner::__private::Matrix::<7, 7>::zeros();
        m[(0, 0)] = self.ra * (self.m1 * self.ra)
            + self.m2 * (self.rr.powi(2) - self.rr * (2.0 * self.da) * s2 + s3) + self.i1
            + self.i2;
        m[(0, 1)] = s4;
        m[(1, 0)] = s4;
        m[(1, 1)] = self.i2 + self.da * (self.m2 * self.da);
        m[(2, 2)] = self.m3 * (self.sa.powi(2) + self.sb.powi(2)) + self.i3;
        m[(3, 3)] = s0 * (self.m4 * s0) + self.i4;
        m[(3, 4)] = s7;
        m[(4, 3)] = s7;
        m[(4, 4)] = self.i4
            + self.m4 * (s5 + self.zt.powi(2) + s6 * (s0 * (2.0 * self.zt)))
            + self.m5 * (self.ta.powi(2) + self.tb.powi(2)) + self.i5;
        m[(5, 5)] = s1 * (self.m6 * s1) + self.i6;
        m[(5, 6)] = s10;
        m[(6, 5)] = s10;
        m[(6, 6)] = self.i6
            + self.m6 * (s8 - s9 * (s1 * (2.0 * self.u)) + self.u.powi(2))
            + self.m7 * (self.ua.powi(2) + self.ub.powi(2)) + self.i7;
        ::zeitner::__private::FullMass(m)
    }
    #[inline]
    fn applied_force(
        &self,
        q: &::zeitner::__private::Vector<7>,
        v: &::zeitner::__private::Vector<7>,
        t: ::zeitner::__private::Float,
    ) -> ::zeitner::__private::Vector<7> {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let s0 = q[2].cos();
        let s1 = q[2].sin();
        let s2 = self.sd * s0 + self.sc * s1;
        let s3 = self.sd * s1;
        let s4 = s0 * self.sc;
        let s5 = s2 + self.xb - self.xc;
        let s6 = s3 - s4 + self.yb - self.yc;
        let s7 = (s5.powi(2) + s6.powi(2)).sqrt();
        let s8 = self.c0 * (s7 - self.l0) / s7;
        let s9 = self.rr * (self.m2 * self.da);
        let s10 = q[1].sin();
        let s11 = (self.e - self.ea) * (self.m4 * self.zt);
        let s12 = q[3].cos();
        let s13 = (self.zf - self.fa) * (self.m6 * self.u);
        let s14 = q[5].cos();
        let mut f = ::zeitner::__private::Vector::<7>::zeros();
        f[0] = self.mom - v[1] * s9 * (v[1] + 2.0 * v[0]) * s10;
        f[1] = s10 * (v[0] * (v[0] * s9));
        f[2] = -(s5 * s8 * (s4 - s3)) - s2 * (s6 * s8);
        f[3] = v[4] * (v[4] * s11) * s12;
        f[4] = -(s12 * (v[3] * s11 * (v[3] + 2.0 * v[4])));
        f[5] = -(v[6] * (v[6] * s13) * s14);
        f[6] = s14 * (v[5] * s13 * (v[5] + 2.0 * v[6]));
        f
    }
    #[inline]
    fn constraint_residual(
        &self,
        q: &::zeitner::__private::Vector<7>,
        v: &::zeitner::__private::Vector<7>,
        t: ::zeitner::__private::Float,
    ) -> ::zeitner::__private::Vector<6> {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let s0 = q[0] + q[1];
        let s1 = self.rr * q[0].cos() - self.d * s0.cos();
        let s2 = self.rr * q[0].sin() - self.d * s0.sin();
        let s3 = q[3] + q[4];
        let s4 = q[5] + q[6];
        let mut g = ::zeitner::__private::Vector::<6>::zeros();
        g[0] = s1 - q[2].sin() * self.ss - self.xb;
        g[1] = s2 + q[2].cos() * self.ss - self.yb;
        g[2] = s1 - self.e * s3.sin() - self.zt * q[4].cos() - self.xa;
        g[3] = s2 + self.e * s3.cos() - self.zt * q[4].sin() - self.ya;
        g[4] = s1 - self.zf * s4.cos() - self.u * q[6].sin() - self.xa;
        g[5] = s2 - self.zf * s4.sin() + self.u * q[6].cos() - self.ya;
        g
    }
    #[inline]
    fn constraint_jacobian(
        &self,
        q: &::zeitner::__private::Vector<7>,
        v: &::zeitner::__private::Vector<7>,
        t: ::zeitner::__private::Float,
    ) -> ::zeitner::__private::Matrix<6, 7> {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let s0 = q[0] + q[1];
        let s1 = self.d * s0.cos();
        let s2 = self.rr * q[0].cos() - s1;
        let s3 = self.d * s0.sin();
        let s4 = q[3] + q[4];
        let s5 = self.e * s4.cos();
        let s6 = q[5] + q[6];
        let s7 = self.zf * s6.sin();
        let s8 = s3 - self.rr * q[0].sin();
        let s9 = -s1;
        let s10 = -(self.e * s4.sin());
        let s11 = -(self.zf * s6.cos());
        let mut g = ::zeitner::__private::Matrix::<6, 7>::zeros();
        g[(0, 0)] = s8;
        g[(0, 1)] = s3;
        g[(0, 2)] = -(q[2].cos() * self.ss);
        g[(1, 0)] = s2;
        g[(1, 1)] = s9;
        g[(1, 2)] = -(q[2].sin() * self.ss);
        g[(2, 0)] = s8;
        g[(2, 1)] = s3;
        g[(2, 3)] = -s5;
        g[(2, 4)] = self.zt * q[4].sin() - s5;
        g[(3, 0)] = s2;
        g[(3, 1)] = s9;
        g[(3, 3)] = s10;
        g[(3, 4)] = s10 - self.zt * q[4].cos();
        g[(4, 0)] = s8;
        g[(4, 1)] = s3;
        g[(4, 5)] = s7;
        g[(4, 6)] = s7 - self.u * q[6].cos();
        g[(5, 0)] = s2;
        g[(5, 1)] = s9;
        g[(5, 5)] = s11;
        g[(5, 6)] = s11 - self.u * q[6].sin();
        g
    }
    #[inline]
    fn constraint_rate(
        &self,
        q: &::zeitner::__private::Vector<7>,
        v: &::zeitner::__private::Vector<7>,
        t: ::zeitner::__private::Float,
    ) -> ::zeitner::__private::Vector<6> {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let s0 = q[0] + q[1];
        let s1 = self.d * s0.cos();
        let s2 = self.d * s0.sin();
        let s3 = q[3] + q[4];
        let s4 = self.e * s3.sin();
        let s5 = self.e * s3.cos();
        let s6 = q[5] + q[6];
        let s7 = self.zf * s6.cos();
        let s8 = self.zf * s6.sin();
        let s9 = v[0] * (s2 - self.rr * q[0].sin()) + v[1] * s2;
        let s10 = v[0] * (self.rr * q[0].cos() - s1) - v[1] * s1;
        let mut w = ::zeitner::__private::Vector::<6>::zeros();
        w[0] = s9 - v[2] * (q[2].cos() * self.ss);
        w[1] = s10 - v[2] * (q[2].sin() * self.ss);
        w[2] = s9 - v[3] * s5 + v[4] * (self.zt * q[4].sin() - s5);
        w[3] = s10 - v[3] * s4 + v[4] * (-s4 - self.zt * q[4].cos());
        w[4] = s9 + v[5] * s8 + v[6] * (s8 - self.u * q[6].cos());
        w[5] = s10 - v[5] * s7 + v[6] * (-s7 - self.u * q[6].sin());
        w
    }
    #[inline]
    fn constraint_acceleration_bias(
        &self,
        q: &::zeitner::__private::Vector<7>,
        v: &::zeitner::__private::Vector<7>,
        t: ::zeitner::__private::Float,
    ) -> ::zeitner::__private::Vector<6> {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let s0 = q[0] + q[1];
        let s1 = self.d * s0.cos();
        let s2 = self.d * s0.sin();
        let s3 = q[3] + q[4];
        let s4 = self.e * s3.sin();
        let s5 = self.e * s3.cos();
        let s6 = q[5] + q[6];
        let s7 = self.zf * s6.cos();
        let s8 = self.zf * s6.sin();
        let s9 = v[1] * s2;
        let s10 = v[1] * s1;
        let s11 = v[0] * (v[0] * (s1 - self.rr * q[0].cos()) + s10)
            + v[1] * (s10 + v[0] * s1);
        let s12 = v[0] * (v[0] * (s2 - self.rr * q[0].sin()) + s9)
            + v[1] * (s9 + v[0] * s2);
        let s13 = v[3] * s5;
        let s14 = v[3] * s4;
        let s15 = v[5] * s8;
        let s16 = v[5] * s7;
        let mut b = ::zeitner::__private::Vector::<6>::zeros();
        b[0] = s11 + v[2] * (v[2] * (q[2].sin() * self.ss));
        b[1] = s12 - v[2] * (v[2] * (q[2].cos() * self.ss));
        b[2] = s11 + v[3] * (s14 + v[4] * s4)
            + v[4] * (s14 + v[4] * (s4 + self.zt * q[4].cos()));
        b[3] = s12 + v[3] * (-s13 - v[4] * s5)
            + v[4] * (v[4] * (self.zt * q[4].sin() - s5) - s13);
        b[4] = s11 + v[5] * (s16 + v[6] * s7)
            + v[6] * (s16 + v[6] * (s7 + self.u * q[6].sin()));
        b[5] = s12 + v[5] * (s15 + v[6] * s8)
            + v[6] * (s15 + v[6] * (s8 - self.u * q[6].cos()));
        b
    }
    #[inline]
    fn stage(
        &self,
        q: &::zeitner::__private::Vector<7>,
        v: &::zeitner::__private::Vector<7>,
        t: ::zeitner::__private::Float,
    ) -> (
        Self::Mass,
        ::zeitner::__private::Vector<7>,
        ::zeitner::__private::Matrix<6, 7>,
        ::zeitner::__private::Vector<6>,
    ) {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let s0 = self.e - self.ea;
        let s1 = self.zf - self.fa;
        let s2 = q[1].cos();
        let s3 = self.da.powi(2);
        let s4 = self.i2 + self.m2 * (s3 - s2 * (self.rr * self.da));
        let s5 = self.m2 * self.da;
        let s6 = s0.powi(2);
        let s7 = q[3].sin();
        let s8 = self.i4 + self.m4 * (s6 + s0 * self.zt * s7);
        let s9 = s1.powi(2);
        let s10 = q[5].sin();
        let s11 = self.i6 + self.m6 * (s9 - s1 * self.u * s10);
        let s12 = q[2].cos();
        let s13 = q[2].sin();
        let s14 = self.sd * s12 + self.sc * s13;
        let s15 = self.sd * s13;
        let s16 = s12 * self.sc;
        let s17 = s14 + self.xb - self.xc;
        let s18 = s15 - s16 + self.yb - self.yc;
        let s19 = (s17.powi(2) + s18.powi(2)).sqrt();
        let s20 = self.c0 * (s19 - self.l0) / s19;
        let s21 = self.rr * s5;
        let s22 = q[1].sin();
        let s23 = s0 * (self.m4 * self.zt);
        let s24 = q[3].cos();
        let s25 = s1 * (self.m6 * self.u);
        let s26 = q[5].cos();
        let s27 = self.rr * q[0].cos();
        let s28 = q[0] + q[1];
        let s29 = self.d * s28.cos();
        let s30 = s27 - s29;
        let s31 = self.d * s28.sin();
        let s32 = s13 * self.ss;
        let s33 = s12 * self.ss;
        let s34 = q[3] + q[4];
        let s35 = self.e * s34.sin();
        let s36 = self.zt * q[4].cos();
        let s37 = self.e * s34.cos();
        let s38 = q[5] + q[6];
        let s39 = self.zf * s38.cos();
        let s40 = self.u * q[6].sin();
        let s41 = self.zf * s38.sin();
        let s42 = s31 - self.rr * q[0].sin();
        let s43 = -s29;
        let s44 = self.zt * q[4].sin() - s37;
        let s45 = -s35;
        let s46 = s41 - self.u * q[6].cos();
        let s47 = -s39;
        let s48 = v[1] * s31;
        let s49 = v[1] * s29;
        let s50 = v[0] * (v[0] * (s29 - s27) + s49) + v[1] * (s49 + v[0] * s29);
        let s51 = v[0] * (v[0] * s42 + s48) + v[1] * (s48 + v[0] * s31);
        let s52 = v[3] * s37;
        let s53 = v[3] * s35;
        let s54 = v[5] * s41;
        let s55 = v[5] * s39;
        let mut m = ::zeitner::__private::Matrix::<7, 7>::zeros();
        let mut f = ::zeitner::__private::Vector::<7>::zeros();
        let mut g = ::zeitner::__private::Matrix::<6, 7>::zeros();
        let mut b = ::zeitner::__private::Vector::<6>::zeros();
        m[(0, 0)] = self.ra * (self.m1 * self.ra)
            + self.m2 * (self.rr.powi(2) - self.rr * (2.0 * self.da) * s2 + s3) + self.i1
            + self.i2;
        m[(0, 1)] = s4;
        m[(1, 0)] = s4;
        m[(1, 1)] = self.i2 + self.da * s5;
        m[(2, 2)] = self.m3 * (self.sa.powi(2) + self.sb.powi(2)) + self.i3;
        m[(3, 3)] = s0 * (self.m4 * s0) + self.i4;
        m[(3, 4)] = s8;
        m[(4, 3)] = s8;
        m[(4, 4)] = self.i4
            + self.m4 * (s6 + self.zt.powi(2) + s7 * (s0 * (2.0 * self.zt)))
            + self.m5 * (self.ta.powi(2) + self.tb.powi(2)) + self.i5;
        m[(5, 5)] = s1 * (self.m6 * s1) + self.i6;
        m[(5, 6)] = s11;
        m[(6, 5)] = s11;
        m[(6, 6)] = self.i6
            + self.m6 * (s9 - s10 * (s1 * (2.0 * self.u)) + self.u.powi(2))
            + self.m7 * (self.ua.powi(2) + self.ub.powi(2)) + self.i7;
        f[0] = self.mom - v[1] * s21 * (v[1] + 2.0 * v[0]) * s22;
        f[1] = s22 * (v[0] * (v[0] * s21));
        f[2] = -(s17 * s20 * (s16 - s15)) - s14 * (s18 * s20);
        f[3] = v[4] * (v[4] * s23) * s24;
        f[4] = -(s24 * (v[3] * s23 * (v[3] + 2.0 * v[4])));
        f[5] = -(v[6] * (v[6] * s25) * s26);
        f[6] = s26 * (v[5] * s25 * (v[5] + 2.0 * v[6]));
        g[(0, 0)] = s42;
        g[(0, 1)] = s31;
        g[(0, 2)] = -s33;
        g[(1, 0)] = s30;
        g[(1, 1)] = s43;
        g[(1, 2)] = -s32;
        g[(2, 0)] = s42;
        g[(2, 1)] = s31;
        g[(2, 3)] = -s37;
        g[(2, 4)] = s44;
        g[(3, 0)] = s30;
        g[(3, 1)] = s43;
        g[(3, 3)] = s45;
        g[(3, 4)] = s45 - s36;
        g[(4, 0)] = s42;
        g[(4, 1)] = s31;
        g[(4, 5)] = s41;
        g[(4, 6)] = s46;
        g[(5, 0)] = s30;
        g[(5, 1)] = s43;
        g[(5, 5)] = s47;
        g[(5, 6)] = s47 - s40;
        b[0] = s50 + v[2] * (v[2] * s32);
        b[1] = s51 - v[2] * (v[2] * s33);
        b[2] = s50 + v[3] * (s53 + v[4] * s35) + v[4] * (s53 + v[4] * (s35 + s36));
        b[3] = s51 + v[3] * (-s52 - v[4] * s37) + v[4] * (v[4] * s44 - s52);
        b[4] = s50 + v[5] * (s55 + v[6] * s39) + v[6] * (s55 + v[6] * (s39 + s40));
        b[5] = s51 + v[5] * (s54 + v[6] * s41) + v[6] * (s54 + v[6] * s46);
        (::zeitner::__private::FullMass(m), f, g, b)
    }
    #[inline]
    fn force_jacobians(
        &self,
        q: &::zeitner::__private::Vector<7>,
        v: &::zeitner::__private::Vector<7>,
        t: ::zeitner::__private::Float,
    ) -> (::zeitner::__private::Matrix<7, 7>, ::zeitner::__private::Matrix<7, 7>) {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let s0 = q[1].cos();
        let s1 = q[3].sin();
        let s2 = q[5].sin();
        let s3 = q[2].cos();
        let s4 = self.sd * s3;
        let s5 = q[2].sin();
        let s6 = self.sc * s5;
        let s7 = s4 + s6;
        let s8 = self.sd * s5;
        let s9 = s3 * self.sc;
        let s10 = s7 + self.xb - self.xc;
        let s11 = s8 - s9 + self.yb - self.yc;
        let s12 = (s10.powi(2) + s11.powi(2)).sqrt();
        let s13 = self.c0 * (s12 - self.l0) / s12;
        let s14 = self.rr * (self.m2 * self.da);
        let s15 = v[1] * s14;
        let s16 = v[1] + 2.0 * v[0];
        let s17 = q[1].sin();
        let s18 = v[0] * s14;
        let s19 = s9 - s8;
        let s20 = (self.e - self.ea) * (self.m4 * self.zt);
        let s21 = v[4] * s20;
        let s22 = q[3].cos();
        let s23 = v[3] * s20;
        let s24 = v[3] + 2.0 * v[4];
        let s25 = (self.zf - self.fa) * (self.m6 * self.u);
        let s26 = v[6] * s25;
        let s27 = q[5].cos();
        let s28 = v[5] * s25;
        let s29 = v[5] + 2.0 * v[6];
        let s30 = (s19 * (2.0 * s10) + s7 * (2.0 * s11)) * (1.0 / (2.0 * s12));
        let s31 = (self.c0 * s30 - s13 * s30) / s12;
        let mut dq = ::zeitner::__private::Matrix::<7, 7>::zeros();
        let mut dv = ::zeitner::__private::Matrix::<7, 7>::zeros();
        dq[(0, 1)] = -(s0 * (s15 * s16));
        dq[(1, 1)] = s0 * (v[0] * s18);
        dq[(2, 2)] = -(s19 * (s13 * s19 + s10 * s31) + s10 * s13 * (-s6 - s4))
            - (s11 * s13 * s19 + s7 * (s7 * s13 + s11 * s31));
        dq[(3, 3)] = -(s1 * (v[4] * s21));
        dq[(4, 3)] = s1 * (s23 * s24);
        dq[(5, 5)] = s2 * (v[6] * s26);
        dq[(6, 5)] = -(s2 * (s28 * s29));
        dv[(0, 0)] = -(s17 * (2.0 * s15));
        dv[(0, 1)] = -(s17 * (s15 + s14 * s16));
        dv[(1, 0)] = s17 * (2.0 * s18);
        dv[(3, 4)] = s22 * (2.0 * s21);
        dv[(4, 3)] = -(s22 * (s23 + s20 * s24));
        dv[(4, 4)] = -(s22 * (2.0 * s23));
        dv[(5, 6)] = -(s27 * (2.0 * s26));
        dv[(6, 5)] = s27 * (s28 + s25 * s29);
        dv[(6, 6)] = s27 * (2.0 * s28);
        (dq, dv)
    }
    #[inline]
    fn constraint_force_jacobians(
        &self,
        q: &::zeitner::__private::Vector<7>,
        v: &::zeitner::__private::Vector<7>,
        t: ::zeitner::__private::Float,
        lambda: &::zeitner::__private::Vector<6>,
    ) -> (::zeitner::__private::Matrix<7, 7>, ::zeitner::__private::Matrix<7, 7>) {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let s0 = q[0] + q[1];
        let s1 = self.d * s0.cos();
        let s2 = self.d * s0.sin();
        let s3 = q[3] + q[4];
        let s4 = self.e * s3.sin();
        let s5 = self.e * s3.cos();
        let s6 = q[5] + q[6];
        let s7 = self.zf * s6.cos();
        let s8 = self.zf * s6.sin();
        let s9 = s2 - self.rr * q[0].sin();
        let s10 = s1 - self.rr * q[0].cos();
        let s11 = s1 * lambda[0] + s2 * lambda[1] + s1 * lambda[2] + s2 * lambda[3]
            + s1 * lambda[4] + s2 * lambda[5];
        let s12 = s4 * lambda[2] - s5 * lambda[3];
        let s13 = s7 * lambda[4] + s8 * lambda[5];
        let mut dq = ::zeitner::__private::Matrix::<7, 7>::zeros();
        let mut dv = ::zeitner::__private::Matrix::<7, 7>::zeros();
        dq[(0, 0)] = s10 * lambda[0] + s9 * lambda[1] + s10 * lambda[2] + s9 * lambda[3]
            + s10 * lambda[4] + s9 * lambda[5];
        dq[(0, 1)] = s11;
        dq[(1, 0)] = s11;
        dq[(1, 1)] = s11;
        dq[(2, 2)] = q[2].sin() * self.ss * lambda[0] - q[2].cos() * self.ss * lambda[1];
        dq[(3, 3)] = s12;
        dq[(3, 4)] = s12;
        dq[(4, 3)] = s12;
        dq[(4, 4)] = (s4 + self.zt * q[4].cos()) * lambda[2]
            + (self.zt * q[4].sin() - s5) * lambda[3];
        dq[(5, 5)] = s13;
        dq[(5, 6)] = s13;
        dq[(6, 5)] = s13;
        dq[(6, 6)] = (s7 + self.u * q[6].sin()) * lambda[4]
            + (s8 - self.u * q[6].cos()) * lambda[5];
        (dq, dv)
    }
    #[inline]
    fn mass_jacobian_product(
        &self,
        q: &::zeitner::__private::Vector<7>,
        t: ::zeitner::__private::Float,
        a: &::zeitner::__private::Vector<7>,
    ) -> ::zeitner::__private::Matrix<7, 7> {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let s0 = self.e - self.ea;
        let s1 = self.zf - self.fa;
        let s2 = q[1].sin();
        let s3 = q[3].cos();
        let s4 = q[5].cos();
        let s5 = self.m2 * (self.rr * self.da * s2);
        let s6 = self.m4 * (s0 * self.zt * s3);
        let s7 = self.m6 * (s1 * self.u * s4);
        let mut dq = ::zeitner::__private::Matrix::<7, 7>::zeros();
        dq[(0, 1)] = a[0] * (self.m2 * (self.rr * (2.0 * self.da) * s2)) + a[1] * s5;
        dq[(1, 1)] = a[0] * s5;
        dq[(3, 3)] = a[4] * s6;
        dq[(4, 3)] = a[3] * s6 + a[4] * (self.m4 * (s0 * (2.0 * self.zt) * s3));
        dq[(5, 5)] = -(a[6] * s7);
        dq[(6, 5)] = -(a[5] * s7) - a[6] * (self.m6 * (s1 * (2.0 * self.u) * s4));
        dq
    }
    #[inline]
    fn constraint_jacobian_nonzeros(
        &self,
        q: &::zeitner::__private::Vector<7>,
        v: &::zeitner::__private::Vector<7>,
        t: ::zeitner::__private::Float,
        values: &mut [::zeitner::__private::Float],
    ) {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let s0 = q[0] + q[1];
        let s1 = self.d * s0.cos();
        let s2 = self.rr * q[0].cos() - s1;
        let s3 = self.d * s0.sin();
        let s4 = q[3] + q[4];
        let s5 = self.e * s4.cos();
        let s6 = q[5] + q[6];
        let s7 = self.zf * s6.sin();
        let s8 = s3 - self.rr * q[0].sin();
        let s9 = -s1;
        let s10 = -(self.e * s4.sin());
        let s11 = -(self.zf * s6.cos());
        values[0] = s8;
        values[1] = s3;
        values[2] = -(q[2].cos() * self.ss);
        values[3] = s2;
        values[4] = s9;
        values[5] = -(q[2].sin() * self.ss);
        values[6] = s8;
        values[7] = s3;
        values[8] = -s5;
        values[9] = self.zt * q[4].sin() - s5;
        values[10] = s2;
        values[11] = s9;
        values[12] = s10;
        values[13] = s10 - self.zt * q[4].cos();
        values[14] = s8;
        values[15] = s3;
        values[16] = s7;
        values[17] = s7 - self.u * q[6].cos();
        values[18] = s2;
        values[19] = s9;
        values[20] = s11;
        values[21] = s11 - self.u * q[6].sin();
    }
    #[inline]
    fn force_jacobian_nonzeros(
        &self,
        q: &::zeitner::__private::Vector<7>,
        v: &::zeitner::__private::Vector<7>,
        t: ::zeitner::__private::Float,
        values: &mut [::zeitner::__private::Float],
    ) {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let s0 = q[1].cos();
        let s1 = q[3].sin();
        let s2 = q[5].sin();
        let s3 = q[2].cos();
        let s4 = self.sd * s3;
        let s5 = q[2].sin();
        let s6 = self.sc * s5;
        let s7 = s4 + s6;
        let s8 = self.sd * s5;
        let s9 = s3 * self.sc;
        let s10 = s7 + self.xb - self.xc;
        let s11 = s8 - s9 + self.yb - self.yc;
        let s12 = (s10.powi(2) + s11.powi(2)).sqrt();
        let s13 = self.c0 * (s12 - self.l0) / s12;
        let s14 = self.rr * (self.m2 * self.da);
        let s15 = v[1] * s14;
        let s16 = v[1] + 2.0 * v[0];
        let s17 = q[1].sin();
        let s18 = v[0] * s14;
        let s19 = s9 - s8;
        let s20 = (self.e - self.ea) * (self.m4 * self.zt);
        let s21 = v[4] * s20;
        let s22 = q[3].cos();
        let s23 = v[3] * s20;
        let s24 = v[3] + 2.0 * v[4];
        let s25 = (self.zf - self.fa) * (self.m6 * self.u);
        let s26 = v[6] * s25;
        let s27 = q[5].cos();
        let s28 = v[5] * s25;
        let s29 = v[5] + 2.0 * v[6];
        let s30 = (s19 * (2.0 * s10) + s7 * (2.0 * s11)) * (1.0 / (2.0 * s12));
        let s31 = (self.c0 * s30 - s13 * s30) / s12;
        values[0] = -(s0 * (s15 * s16));
        values[1] = s0 * (v[0] * s18);
        values[2] = -(s19 * (s13 * s19 + s10 * s31) + s10 * s13 * (-s6 - s4))
            - (s11 * s13 * s19 + s7 * (s7 * s13 + s11 * s31));
        values[3] = -(s1 * (v[4] * s21));
        values[4] = s1 * (s23 * s24);
        values[5] = s2 * (v[6] * s26);
        values[6] = -(s2 * (s28 * s29));
        values[7] = -(s17 * (2.0 * s15));
        values[8] = -(s17 * (s15 + s14 * s16));
        values[9] = s17 * (2.0 * s18);
        values[10] = s22 * (2.0 * s21);
        values[11] = -(s22 * (s23 + s20 * s24));
        values[12] = -(s22 * (2.0 * s23));
        values[13] = -(s27 * (2.0 * s26));
        values[14] = s27 * (s28 + s25 * s29);
        values[15] = s27 * (2.0 * s28);
    }
    #[inline]
    fn constraint_force_jacobian_nonzeros(
        &self,
        q: &::zeitner::__private::Vector<7>,
        v: &::zeitner::__private::Vector<7>,
        t: ::zeitner::__private::Float,
        lambda: &::zeitner::__private::Vector<6>,
        values: &mut [::zeitner::__private::Float],
    ) {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let s0 = q[0] + q[1];
        let s1 = self.d * s0.cos();
        let s2 = self.d * s0.sin();
        let s3 = q[3] + q[4];
        let s4 = self.e * s3.sin();
        let s5 = self.e * s3.cos();
        let s6 = q[5] + q[6];
        let s7 = self.zf * s6.cos();
        let s8 = self.zf * s6.sin();
        let s9 = s2 - self.rr * q[0].sin();
        let s10 = s1 - self.rr * q[0].cos();
        let s11 = s1 * lambda[0] + s2 * lambda[1] + s1 * lambda[2] + s2 * lambda[3]
            + s1 * lambda[4] + s2 * lambda[5];
        let s12 = s4 * lambda[2] - s5 * lambda[3];
        let s13 = s7 * lambda[4] + s8 * lambda[5];
        values[0] = s10 * lambda[0] + s9 * lambda[1] + s10 * lambda[2] + s9 * lambda[3]
            + s10 * lambda[4] + s9 * lambda[5];
        values[1] = s11;
        values[2] = s11;
        values[3] = s11;
        values[4] = q[2].sin() * self.ss * lambda[0] - q[2].cos() * self.ss * lambda[1];
        values[5] = s12;
        values[6] = s12;
        values[7] = s12;
        values[8] = (s4 + self.zt * q[4].cos()) * lambda[2]
            + (self.zt * q[4].sin() - s5) * lambda[3];
        values[9] = s13;
        values[10] = s13;
        values[11] = s13;
        values[12] = (s7 + self.u * q[6].sin()) * lambda[4]
            + (s8 - self.u * q[6].cos()) * lambda[5];
    }
}
#[allow(unused_variables, unused_mut, clippy::all)]
impl ::zeitner::__private::ParametrisedSystem<7, 6, 4> for Andrews {
    const PARAMETER_NAMES: [&'static str; 4] = ["mom", "c0", "m2", "d"];
    #[inline]
    fn parameter_values(&self) -> ::zeitner::__private::Vector<4> {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let mut theta = ::zeitner::__private::Vector::<4>::zeros();
        theta[0] = self.mom;
        theta[1] = self.c0;
        theta[2] = self.m2;
        theta[3] = self.d;
        theta
    }
    #[inline]
    fn parameter_force(
        &self,
        q: &::zeitner::__private::Vector<7>,
        v: &::zeitner::__private::Vector<7>,
        t: ::zeitner::__private::Float,
        lambda: &::zeitner::__private::Vector<6>,
        a: &::zeitner::__private::Vector<7>,
    ) -> ::zeitner::__private::Matrix<7, 4> {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let s0 = q[1].cos();
        let s1 = self.da.powi(2);
        let s2 = self.rr * self.da;
        let s3 = s1 - s0 * s2;
        let s4 = q[2].cos();
        let s5 = q[2].sin();
        let s6 = self.sd * s4 + self.sc * s5;
        let s7 = self.sd * s5;
        let s8 = s4 * self.sc;
        let s9 = s6 + self.xb - self.xc;
        let s10 = s7 - s8 + self.yb - self.yc;
        let s11 = (s9.powi(2) + s10.powi(2)).sqrt();
        let s12 = q[1].sin();
        let s13 = q[0] + q[1];
        let s14 = s13.cos();
        let s15 = s13.sin();
        let s16 = s14 * lambda[1] - s15 * lambda[0] - s15 * lambda[2] + s14 * lambda[3]
            - s15 * lambda[4] + s14 * lambda[5];
        let s17 = (s11 - self.l0) / s11;
        let mut df = ::zeitner::__private::Matrix::<7, 4>::zeros();
        df[(0, 0)] = 1.0;
        df[(0, 2)] = -(s12 * ((v[1] + 2.0 * v[0]) * (s2 * v[1])))
            - (self.rr.powi(2) - self.rr * (2.0 * self.da) * s0 + s1) * a[0] - s3 * a[1];
        df[(0, 3)] = s16;
        df[(1, 2)] = s12 * (v[0] * (s2 * v[0])) - s3 * a[0] - s1 * a[1];
        df[(1, 3)] = s16;
        df[(2, 1)] = -((s8 - s7) * (s9 * s17)) - s6 * (s10 * s17);
        df
    }
    #[inline]
    fn parameter_constraints(
        &self,
        q: &::zeitner::__private::Vector<7>,
        v: &::zeitner::__private::Vector<7>,
        t: ::zeitner::__private::Float,
    ) -> (::zeitner::__private::Matrix<6, 4>, ::zeitner::__private::Matrix<6, 4>) {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let s0 = q[0] + q[1];
        let s1 = s0.cos();
        let s2 = s0.sin();
        let s3 = -s2;
        let s4 = -s1;
        let s5 = v[0] * s2 + v[1] * s2;
        let s6 = -(v[0] * s1) - v[1] * s1;
        let mut dg = ::zeitner::__private::Matrix::<6, 4>::zeros();
        let mut dw = ::zeitner::__private::Matrix::<6, 4>::zeros();
        dg[(0, 3)] = s4;
        dg[(1, 3)] = s3;
        dg[(2, 3)] = s4;
        dg[(3, 3)] = s3;
        dg[(4, 3)] = s4;
        dg[(5, 3)] = s3;
        dw[(0, 3)] = s5;
        dw[(1, 3)] = s6;
        dw[(2, 3)] = s5;
        dw[(3, 3)] = s6;
        dw[(4, 3)] = s5;
        dw[(5, 3)] = s6;
        (dg, dw)
    }
    #[inline]
    fn rate_jacobians(
        &self,
        q: &::zeitner::__private::Vector<7>,
        v: &::zeitner::__private::Vector<7>,
        t: ::zeitner::__private::Float,
    ) -> (::zeitner::__private::Matrix<6, 7>, ::zeitner::__private::Matrix<6, 7>) {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let s0 = self.rr * q[0].cos();
        let s1 = q[0] + q[1];
        let s2 = self.d * s1.cos();
        let s3 = s0 - s2;
        let s4 = self.d * s1.sin();
        let s5 = q[2].sin() * self.ss;
        let s6 = q[2].cos() * self.ss;
        let s7 = q[3] + q[4];
        let s8 = self.e * s7.sin();
        let s9 = self.zt * q[4].cos();
        let s10 = self.e * s7.cos();
        let s11 = q[5] + q[6];
        let s12 = self.zf * s11.cos();
        let s13 = self.u * q[6].sin();
        let s14 = self.zf * s11.sin();
        let s15 = s4 - self.rr * q[0].sin();
        let s16 = -s2;
        let s17 = self.zt * q[4].sin() - s10;
        let s18 = -s8;
        let s19 = s14 - self.u * q[6].cos();
        let s20 = -s12;
        let s21 = v[1] * s4;
        let s22 = v[0] * s15 + s21;
        let s23 = v[1] * s2;
        let s24 = v[0] * (s2 - s0) + s23;
        let s25 = s23 + v[0] * s2;
        let s26 = s21 + v[0] * s4;
        let s27 = v[3] * s10;
        let s28 = v[3] * s8;
        let s29 = v[5] * s14;
        let s30 = v[5] * s12;
        let mut wq = ::zeitner::__private::Matrix::<6, 7>::zeros();
        let mut wv = ::zeitner::__private::Matrix::<6, 7>::zeros();
        wq[(0, 0)] = s24;
        wq[(0, 1)] = s25;
        wq[(0, 2)] = v[2] * s5;
        wq[(1, 0)] = s22;
        wq[(1, 1)] = s26;
        wq[(1, 2)] = -(v[2] * s6);
        wq[(2, 0)] = s24;
        wq[(2, 1)] = s25;
        wq[(2, 3)] = s28 + v[4] * s8;
        wq[(2, 4)] = s28 + v[4] * (s8 + s9);
        wq[(3, 0)] = s22;
        wq[(3, 1)] = s26;
        wq[(3, 3)] = -s27 - v[4] * s10;
        wq[(3, 4)] = v[4] * s17 - s27;
        wq[(4, 0)] = s24;
        wq[(4, 1)] = s25;
        wq[(4, 5)] = s30 + v[6] * s12;
        wq[(4, 6)] = s30 + v[6] * (s12 + s13);
        wq[(5, 0)] = s22;
        wq[(5, 1)] = s26;
        wq[(5, 5)] = s29 + v[6] * s14;
        wq[(5, 6)] = s29 + v[6] * s19;
        wv[(0, 0)] = s15;
        wv[(0, 1)] = s4;
        wv[(0, 2)] = -s6;
        wv[(1, 0)] = s3;
        wv[(1, 1)] = s16;
        wv[(1, 2)] = -s5;
        wv[(2, 0)] = s15;
        wv[(2, 1)] = s4;
        wv[(2, 3)] = -s10;
        wv[(2, 4)] = s17;
        wv[(3, 0)] = s3;
        wv[(3, 1)] = s16;
        wv[(3, 3)] = s18;
        wv[(3, 4)] = s18 - s9;
        wv[(4, 0)] = s15;
        wv[(4, 1)] = s4;
        wv[(4, 5)] = s14;
        wv[(4, 6)] = s19;
        wv[(5, 0)] = s3;
        wv[(5, 1)] = s16;
        wv[(5, 5)] = s20;
        wv[(5, 6)] = s20 - s13;
        (wq, wv)
    }
    #[inline]
    fn acceleration_constraint_jacobians(
        &self,
        q: &::zeitner::__private::Vector<7>,
        v: &::zeitner::__private::Vector<7>,
        t: ::zeitner::__private::Float,
        a: &::zeitner::__private::Vector<7>,
    ) -> (
        ::zeitner::__private::Matrix<6, 7>,
        ::zeitner::__private::Matrix<6, 7>,
        ::zeitner::__private::Matrix<6, 4>,
    ) {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let s0 = q[0] + q[1];
        let s1 = s0.cos();
        let s2 = self.d * s1;
        let s3 = self.rr * q[0].sin();
        let s4 = s0.sin();
        let s5 = self.d * s4;
        let s6 = q[2].sin() * self.ss;
        let s7 = q[2].cos() * self.ss;
        let s8 = q[3] + q[4];
        let s9 = self.e * s8.sin();
        let s10 = self.e * s8.cos();
        let s11 = self.zt * q[4].sin();
        let s12 = q[5] + q[6];
        let s13 = self.zf * s12.cos();
        let s14 = self.zf * s12.sin();
        let s15 = self.u * q[6].cos();
        let s16 = s5 - s3;
        let s17 = s11 - s10;
        let s18 = s14 - s15;
        let s19 = v[0] * s16;
        let s20 = v[1] * s5;
        let s21 = v[2] * s7;
        let s22 = s2 - self.rr * q[0].cos();
        let s23 = v[0] * s22;
        let s24 = v[1] * s2;
        let s25 = s23 + s24;
        let s26 = v[0] * s2;
        let s27 = s24 + s26;
        let s28 = v[1] * s27;
        let s29 = v[2] * s6;
        let s30 = v[0] * s5;
        let s31 = v[3] * s10;
        let s32 = v[4] * s17;
        let s33 = v[3] * s9;
        let s34 = v[4] * s9;
        let s35 = s33 + s34;
        let s36 = v[3] * s35;
        let s37 = s9 + self.zt * q[4].cos();
        let s38 = v[4] * s37;
        let s39 = s33 + s38;
        let s40 = v[4] * s10;
        let s41 = v[5] * s14;
        let s42 = v[6] * s18;
        let s43 = v[5] * s13;
        let s44 = v[6] * s13;
        let s45 = s43 + s44;
        let s46 = v[5] * s45;
        let s47 = s13 + self.u * q[6].sin();
        let s48 = v[6] * s47;
        let s49 = s43 + s48;
        let s50 = v[6] * s14;
        let s51 = v[0] * s4 + v[1] * s4;
        let s52 = s5 * a[1];
        let s53 = s2 * a[1];
        let s54 = s10 * a[3];
        let s55 = s9 * a[3];
        let s56 = s14 * a[5];
        let s57 = s13 * a[5];
        let s58 = v[1] * (-s20 - s30);
        let s59 = s53 + v[0] * (v[0] * (s3 - s5) - s20) + s58 + s22 * a[0];
        let s60 = s53 + s58 + v[0] * (-s30 - s20) + s2 * a[0];
        let s61 = s24 + s23 + s25;
        let s62 = s26 + s24 + s27;
        let s63 = s52 + v[0] * s25 + s28 + s16 * a[0];
        let s64 = s52 + s28 + v[0] * s27 + s5 * a[0];
        let s65 = s20 + s19 + s19 + s20;
        let s66 = s30 + s20 + s20 + s30;
        let s67 = s31 + s40;
        let s68 = v[3] * s67;
        let s69 = -s41 - s50;
        let s70 = v[5] * s69;
        let s71 = v[0] * s1 + v[1] * s1;
        let s72 = v[0] * s71 + v[1] * s71 + s4 * a[0] + s4 * a[1];
        let s73 = v[0] * s51 + v[1] * s51 - s1 * a[0] - s1 * a[1];
        let mut cq = ::zeitner::__private::Matrix::<6, 7>::zeros();
        let mut cv = ::zeitner::__private::Matrix::<6, 7>::zeros();
        let mut cp = ::zeitner::__private::Matrix::<6, 4>::zeros();
        cq[(0, 0)] = s59;
        cq[(0, 1)] = s60;
        cq[(0, 2)] = v[2] * s21 + s6 * a[2];
        cq[(1, 0)] = s63;
        cq[(1, 1)] = s64;
        cq[(1, 2)] = v[2] * s29 - s7 * a[2];
        cq[(2, 0)] = s59;
        cq[(2, 1)] = s60;
        cq[(2, 3)] = s55 + s68 + v[4] * s67 + s9 * a[4];
        cq[(2, 4)] = s55 + s68 + v[4] * (s31 + v[4] * (s10 - s11)) + s37 * a[4];
        cq[(3, 0)] = s63;
        cq[(3, 1)] = s64;
        cq[(3, 3)] = s36 + v[4] * s35 - s54 - s10 * a[4];
        cq[(3, 4)] = s17 * a[4] + s36 + v[4] * s39 - s54;
        cq[(4, 0)] = s59;
        cq[(4, 1)] = s60;
        cq[(4, 5)] = s57 + s70 + v[6] * s69 + s13 * a[6];
        cq[(4, 6)] = s57 + s70 + v[6] * (v[6] * (s15 - s14) - s41) + s47 * a[6];
        cq[(5, 0)] = s63;
        cq[(5, 1)] = s64;
        cq[(5, 5)] = s56 + s46 + v[6] * s45 + s14 * a[6];
        cq[(5, 6)] = s18 * a[6] + s56 + s46 + v[6] * s49;
        cv[(0, 0)] = s61;
        cv[(0, 1)] = s62;
        cv[(0, 2)] = 2.0 * s29;
        cv[(1, 0)] = s65;
        cv[(1, 1)] = s66;
        cv[(1, 2)] = -(2.0 * s21);
        cv[(2, 0)] = s61;
        cv[(2, 1)] = s62;
        cv[(2, 3)] = s34 + s33 + s35;
        cv[(2, 4)] = s33 + s38 + s39;
        cv[(3, 0)] = s65;
        cv[(3, 1)] = s66;
        cv[(3, 3)] = -s31 - s40 - s31 - s40;
        cv[(3, 4)] = s32 + s32 - s31 - s31;
        cv[(4, 0)] = s61;
        cv[(4, 1)] = s62;
        cv[(4, 5)] = s44 + s43 + s45;
        cv[(4, 6)] = s43 + s48 + s49;
        cv[(5, 0)] = s65;
        cv[(5, 1)] = s66;
        cv[(5, 5)] = s50 + s41 + s41 + s50;
        cv[(5, 6)] = s41 + s42 + s41 + s42;
        cp[(0, 3)] = s72;
        cp[(1, 3)] = s73;
        cp[(2, 3)] = s72;
        cp[(3, 3)] = s73;
        cp[(4, 3)] = s72;
        cp[(5, 3)] = s73;
        (cq, cv, cp)
    }
}
