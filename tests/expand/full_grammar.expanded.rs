#[allow(dead_code)]
impl Everything {
    fn mass(&self, q: [Float; 3], t: Float) -> [[Float; 3]; 3] {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let c = 0.1 * q[2].cos();
        [[self.m + q[0] * q[0], c, 0.0], [c, self.m, 0.0], [0.0, 0.0, self.m + t * 0.0]]
    }
    fn force(
        &self,
        [a,
        b,
        c,
        ]: [Float; 3],
        [u,
        v,
        w,
        ]: [Float; 3],
        t: Float,
    ) -> [Float; 3] {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let load = if t < self.t_off && !(t > 10.0) { self.drive(t) } else { 0.0 };
        let smooth = a.sin() * b.cos() + c.tan() * 0.1 + (a * 0.1).asin()
            + (b * 0.1).acos() + c.atan();
        let more = a.sinh() + b.cosh() + c.tanh() + (a * a + 1.0).ln()
            + (b * b + 2.0).log10() + c.exp();
        let piecewise = a.abs() + b.signum() + c.min(a) + a.max(b) + a.hypot(b)
            + b.atan2(c);
        let powers = a.powi(-2) + (b * b + 1.0).powf(1.5) + (c * c + 1.0).sqrt()
            + Float::sin(a);
        [
            load - self.k * u + smooth,
            -v * more + piecewise,
            -w + powers + zeitner::scalar::consts::PI + LENGTH,
        ]
    }
    fn constraints(&self, [a, b, _c]: [Float; 3], t: Float) -> [Float; 1] {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        [a * a + b * b - LENGTH * LENGTH * (1.0 + 0.1 * (t * 2.0).sin())]
    }
    fn velocity_constraints(
        &self,
        [_a,
        _b,
        c,
        ]: [Float; 3],
        [_u,
        _v,
        w,
        ]: [Float; 3],
        t: Float,
    ) -> [Float; 1] {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        [w - c * 0.5 - t]
    }
}
#[allow(unused_variables, unused_mut, clippy::all)]
impl ::zeitner::__private::ConstrainedSystem<3, 2> for Everything {
    const POSITION_CONSTRAINTS: usize = 1;
    const MASS_IS_CONSTANT: bool = false;
    const DYNAMICS_DEPEND_ON_VELOCITY: bool = true;
    const SUMMARY: ::zeitner::__private::SceneSummary = ::zeitner::__private::SceneSummary {
        coordinates: 3,
        position_constraints: 1,
        velocity_constraints: 1,
        mass: ::zeitner::__private::MassKind::Full,
        time_dependent: true,
        functions: &[
            ::zeitner::__private::FunctionSummary {
                name: "mass_matrix",
                blocks: &[
                    ::zeitner::__private::BlockSummary {
                        name: "m",
                        rows: 3,
                        cols: 3,
                        nonzeros: &[(0, 0), (0, 1), (1, 0), (1, 1), (2, 2)],
                    },
                ],
                ops: ::zeitner::__private::OpCounts {
                    adds: 1u64,
                    muls: 2u64,
                    divs: 0u64,
                    transcendental: 1u64,
                    opaque_calls: 0u64,
                },
                ops_unshared: ::zeitner::__private::OpCounts {
                    adds: 1u64,
                    muls: 3u64,
                    divs: 0u64,
                    transcendental: 2u64,
                    opaque_calls: 0u64,
                },
            },
            ::zeitner::__private::FunctionSummary {
                name: "applied_force",
                blocks: &[
                    ::zeitner::__private::BlockSummary {
                        name: "f",
                        rows: 3,
                        cols: 1,
                        nonzeros: &[(0, 0), (1, 0), (2, 0)],
                    },
                ],
                ops: ::zeitner::__private::OpCounts {
                    adds: 27u64,
                    muls: 10u64,
                    divs: 0u64,
                    transcendental: 20u64,
                    opaque_calls: 1u64,
                },
                ops_unshared: ::zeitner::__private::OpCounts {
                    adds: 27u64,
                    muls: 11u64,
                    divs: 0u64,
                    transcendental: 21u64,
                    opaque_calls: 1u64,
                },
            },
            ::zeitner::__private::FunctionSummary {
                name: "constraint_residual",
                blocks: &[
                    ::zeitner::__private::BlockSummary {
                        name: "g",
                        rows: 2,
                        cols: 1,
                        nonzeros: &[(0, 0), (1, 0)],
                    },
                ],
                ops: ::zeitner::__private::OpCounts {
                    adds: 5u64,
                    muls: 7u64,
                    divs: 0u64,
                    transcendental: 1u64,
                    opaque_calls: 0u64,
                },
                ops_unshared: ::zeitner::__private::OpCounts {
                    adds: 5u64,
                    muls: 7u64,
                    divs: 0u64,
                    transcendental: 1u64,
                    opaque_calls: 0u64,
                },
            },
            ::zeitner::__private::FunctionSummary {
                name: "constraint_jacobian",
                blocks: &[
                    ::zeitner::__private::BlockSummary {
                        name: "g",
                        rows: 2,
                        cols: 3,
                        nonzeros: &[(0, 0), (0, 1), (1, 2)],
                    },
                ],
                ops: ::zeitner::__private::OpCounts {
                    adds: 0u64,
                    muls: 2u64,
                    divs: 0u64,
                    transcendental: 0u64,
                    opaque_calls: 0u64,
                },
                ops_unshared: ::zeitner::__private::OpCounts {
                    adds: 0u64,
                    muls: 2u64,
                    divs: 0u64,
                    transcendental: 0u64,
                    opaque_calls: 0u64,
                },
            },
            ::zeitner::__private::FunctionSummary {
                name: "constraint_position_partials",
                blocks: &[
                    ::zeitner::__private::BlockSummary {
                        name: "p",
                        rows: 2,
                        cols: 3,
                        nonzeros: &[(0, 0), (0, 1), (1, 2)],
                    },
                ],
                ops: ::zeitner::__private::OpCounts {
                    adds: 0u64,
                    muls: 2u64,
                    divs: 0u64,
                    transcendental: 0u64,
                    opaque_calls: 0u64,
                },
                ops_unshared: ::zeitner::__private::OpCounts {
                    adds: 0u64,
                    muls: 2u64,
                    divs: 0u64,
                    transcendental: 0u64,
                    opaque_calls: 0u64,
                },
            },
            ::zeitner::__private::FunctionSummary {
                name: "constraint_rate",
                blocks: &[
                    ::zeitner::__private::BlockSummary {
                        name: "w",
                        rows: 2,
                        cols: 1,
                        nonzeros: &[(0, 0), (1, 0)],
                    },
                ],
                ops: ::zeitner::__private::OpCounts {
                    adds: 4u64,
                    muls: 10u64,
                    divs: 0u64,
                    transcendental: 1u64,
                    opaque_calls: 0u64,
                },
                ops_unshared: ::zeitner::__private::OpCounts {
                    adds: 4u64,
                    muls: 10u64,
                    divs: 0u64,
                    transcendental: 1u64,
                    opaque_calls: 0u64,
                },
            },
            ::zeitner::__private::FunctionSummary {
                name: "constraint_acceleration_bias",
                blocks: &[
                    ::zeitner::__private::BlockSummary {
                        name: "b",
                        rows: 2,
                        cols: 1,
                        nonzeros: &[(0, 0), (1, 0)],
                    },
                ],
                ops: ::zeitner::__private::OpCounts {
                    adds: 3u64,
                    muls: 11u64,
                    divs: 0u64,
                    transcendental: 1u64,
                    opaque_calls: 0u64,
                },
                ops_unshared: ::zeitner::__private::OpCounts {
                    adds: 3u64,
                    muls: 11u64,
                    divs: 0u64,
                    transcendental: 1u64,
                    opaque_calls: 0u64,
                },
            },
            ::zeitner::__private::FunctionSummary {
                name: "stage",
                blocks: &[
                    ::zeitner::__private::BlockSummary {
                        name: "m",
                        rows: 3,
                        cols: 3,
                        nonzeros: &[(0, 0), (0, 1), (1, 0), (1, 1), (2, 2)],
                    },
                    ::zeitner::__private::BlockSummary {
                        name: "f",
                        rows: 3,
                        cols: 1,
                        nonzeros: &[(0, 0), (1, 0), (2, 0)],
                    },
                    ::zeitner::__private::BlockSummary {
                        name: "g",
                        rows: 2,
                        cols: 3,
                        nonzeros: &[(0, 0), (0, 1), (1, 2)],
                    },
                    ::zeitner::__private::BlockSummary {
                        name: "b",
                        rows: 2,
                        cols: 1,
                        nonzeros: &[(0, 0), (1, 0)],
                    },
                ],
                ops: ::zeitner::__private::OpCounts {
                    adds: 31u64,
                    muls: 24u64,
                    divs: 0u64,
                    transcendental: 22u64,
                    opaque_calls: 1u64,
                },
                ops_unshared: ::zeitner::__private::OpCounts {
                    adds: 31u64,
                    muls: 27u64,
                    divs: 0u64,
                    transcendental: 24u64,
                    opaque_calls: 1u64,
                },
            },
            ::zeitner::__private::FunctionSummary {
                name: "force_jacobians",
                blocks: &[
                    ::zeitner::__private::BlockSummary {
                        name: "dq",
                        rows: 3,
                        cols: 3,
                        nonzeros: &[
                            (0, 0),
                            (0, 1),
                            (0, 2),
                            (1, 0),
                            (1, 1),
                            (1, 2),
                            (2, 0),
                            (2, 1),
                            (2, 2),
                        ],
                    },
                    ::zeitner::__private::BlockSummary {
                        name: "dv",
                        rows: 3,
                        cols: 3,
                        nonzeros: &[(0, 0), (1, 1), (2, 2)],
                    },
                ],
                ops: ::zeitner::__private::OpCounts {
                    adds: 33u64,
                    muls: 30u64,
                    divs: 11u64,
                    transcendental: 19u64,
                    opaque_calls: 0u64,
                },
                ops_unshared: ::zeitner::__private::OpCounts {
                    adds: 38u64,
                    muls: 41u64,
                    divs: 11u64,
                    transcendental: 23u64,
                    opaque_calls: 0u64,
                },
            },
            ::zeitner::__private::FunctionSummary {
                name: "constraint_force_jacobians",
                blocks: &[
                    ::zeitner::__private::BlockSummary {
                        name: "dq",
                        rows: 3,
                        cols: 3,
                        nonzeros: &[(0, 0), (1, 1)],
                    },
                    ::zeitner::__private::BlockSummary {
                        name: "dv",
                        rows: 3,
                        cols: 3,
                        nonzeros: &[],
                    },
                ],
                ops: ::zeitner::__private::OpCounts {
                    adds: 0u64,
                    muls: 1u64,
                    divs: 0u64,
                    transcendental: 0u64,
                    opaque_calls: 0u64,
                },
                ops_unshared: ::zeitner::__private::OpCounts {
                    adds: 0u64,
                    muls: 2u64,
                    divs: 0u64,
                    transcendental: 0u64,
                    opaque_calls: 0u64,
                },
            },
            ::zeitner::__private::FunctionSummary {
                name: "mass_jacobian_product",
                blocks: &[
                    ::zeitner::__private::BlockSummary {
                        name: "dq",
                        rows: 3,
                        cols: 3,
                        nonzeros: &[(0, 0), (0, 2), (1, 2)],
                    },
                ],
                ops: ::zeitner::__private::OpCounts {
                    adds: 2u64,
                    muls: 5u64,
                    divs: 0u64,
                    transcendental: 1u64,
                    opaque_calls: 0u64,
                },
                ops_unshared: ::zeitner::__private::OpCounts {
                    adds: 2u64,
                    muls: 6u64,
                    divs: 0u64,
                    transcendental: 2u64,
                    opaque_calls: 0u64,
                },
            },
        ],
    };
    type Mass = ::zeitner::__private::FullMass<3>;
    type Storage = ::zeitner::__private::Dense;
    const SPARSITY: ::core::option::Option<::zeitner::__private::Sparsity> = ::core::option::Option::Some(::zeitner::__private::Sparsity {
        constraint_jacobian: &[(0, 0), (0, 1), (1, 2)],
        force_jacobians: [
            &[(0, 0), (0, 1), (0, 2), (1, 0), (1, 1), (1, 2), (2, 0), (2, 1), (2, 2)],
            &[(0, 0), (1, 1), (2, 2)],
        ],
        constraint_force_jacobians: [&[(0, 0), (1, 1)], &[]],
    });
    #[inline]
    fn mass_matrix(
        &self,
        q: &::zeitner::__private::Vector<3>,
        t: ::zeitner::__private::Float,
    ) -> Self::Mass {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let s0 = 0.1 * q[2].cos();
        let mut m = ::zeitner::__private::Matrix::<3, 3>::zeros();
        m[(0, 0)] = self.m + q[0].powi(2);
        m[(0, 1)] = s0;
        m[(1, 0)] = s0;
        m[(1, 1)] = self.m;
        m[(2, 2)] = self.m;
        ::zeitner::__private::FullMass(m)
    }
    #[inline]
    fn applied_force(
        &self,
        q: &::zeitner::__private::Vector<3>,
        v: &::zeitner::__private::Vector<3>,
        t: ::zeitner::__private::Float,
    ) -> ::zeitner::__private::Vector<3> {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let s0 = q[0].sin();
        let s1 = q[1].powi(2);
        let mut f = ::zeitner::__private::Vector::<3>::zeros();
        f[0] = s0 * q[1].cos() + 0.1 * q[2].tan() + (0.1 * q[0]).asin()
            + (0.1 * q[1]).acos() + q[2].atan()
            + (if t < self.t_off && !(t > 10.0) { self.drive(t) } else { 0.0 })
            - v[0] * self.k;
        f[1] = q[0].abs() + q[1].signum() + q[2].min(q[0]) + q[0].max(q[1])
            + q[0].hypot(q[1]) + q[1].atan2(q[2])
            - v[1]
                * (q[0].sinh() + q[1].cosh() + q[2].tanh() + (q[0].powi(2) + 1.0).ln()
                    + (s1 + 2.0).log10() + q[2].exp());
        f[2] = s0 + q[0].powi(-2) + (1.0 + s1).powf(1.5) + (1.0 + q[2].powi(2)).sqrt()
            - v[2] + zeitner::scalar::consts::PI + LENGTH;
        f
    }
    #[inline]
    fn constraint_residual(
        &self,
        q: &::zeitner::__private::Vector<3>,
        v: &::zeitner::__private::Vector<3>,
        t: ::zeitner::__private::Float,
    ) -> ::zeitner::__private::Vector<2> {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let mut g = ::zeitner::__private::Vector::<2>::zeros();
        g[0] = q[0].powi(2) + q[1].powi(2)
            - LENGTH.powi(2) * (1.0 + 0.1 * (2.0 * t).sin());
        g[1] = v[2] - 0.5 * q[2] - t;
        g
    }
    #[inline]
    fn constraint_jacobian(
        &self,
        q: &::zeitner::__private::Vector<3>,
        v: &::zeitner::__private::Vector<3>,
        t: ::zeitner::__private::Float,
    ) -> ::zeitner::__private::Matrix<2, 3> {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let mut g = ::zeitner::__private::Matrix::<2, 3>::zeros();
        g[(0, 0)] = 2.0 * q[0];
        g[(0, 1)] = 2.0 * q[1];
        g[(1, 2)] = 1.0;
        g
    }
    #[inline]
    fn constraint_position_partials(
        &self,
        q: &::zeitner::__private::Vector<3>,
        v: &::zeitner::__private::Vector<3>,
        t: ::zeitner::__private::Float,
    ) -> ::zeitner::__private::Matrix<2, 3> {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let mut p = ::zeitner::__private::Matrix::<2, 3>::zeros();
        p[(0, 0)] = 2.0 * q[0];
        p[(0, 1)] = 2.0 * q[1];
        p[(1, 2)] = -0.5;
        p
    }
    #[inline]
    fn constraint_rate(
        &self,
        q: &::zeitner::__private::Vector<3>,
        v: &::zeitner::__private::Vector<3>,
        t: ::zeitner::__private::Float,
    ) -> ::zeitner::__private::Vector<2> {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let mut w = ::zeitner::__private::Vector::<2>::zeros();
        w[0] = v[0] * (2.0 * q[0]) - LENGTH.powi(2) * (0.1 * (2.0 * (2.0 * t).cos()))
            + v[1] * (2.0 * q[1]);
        w[1] = v[2] - 0.5 * q[2] - t;
        w
    }
    #[inline]
    fn constraint_acceleration_bias(
        &self,
        q: &::zeitner::__private::Vector<3>,
        v: &::zeitner::__private::Vector<3>,
        t: ::zeitner::__private::Float,
    ) -> ::zeitner::__private::Vector<2> {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let mut b = ::zeitner::__private::Vector::<2>::zeros();
        b[0] = LENGTH.powi(2) * (0.1 * (2.0 * (2.0 * (2.0 * t).sin())))
            + v[0] * (2.0 * v[0]) + v[1] * (2.0 * v[1]);
        b[1] = -1.0 + -0.5 * v[2];
        b
    }
    #[inline]
    fn stage(
        &self,
        q: &::zeitner::__private::Vector<3>,
        v: &::zeitner::__private::Vector<3>,
        t: ::zeitner::__private::Float,
    ) -> (
        Self::Mass,
        ::zeitner::__private::Vector<3>,
        ::zeitner::__private::Matrix<2, 3>,
        ::zeitner::__private::Vector<2>,
    ) {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let s0 = 0.1 * q[2].cos();
        let s1 = q[0].powi(2);
        let s2 = q[0].sin();
        let s3 = q[1].powi(2);
        let mut m = ::zeitner::__private::Matrix::<3, 3>::zeros();
        let mut f = ::zeitner::__private::Vector::<3>::zeros();
        let mut g = ::zeitner::__private::Matrix::<2, 3>::zeros();
        let mut b = ::zeitner::__private::Vector::<2>::zeros();
        m[(0, 0)] = self.m + s1;
        m[(0, 1)] = s0;
        m[(1, 0)] = s0;
        m[(1, 1)] = self.m;
        m[(2, 2)] = self.m;
        f[0] = s2 * q[1].cos() + 0.1 * q[2].tan() + (0.1 * q[0]).asin()
            + (0.1 * q[1]).acos() + q[2].atan()
            + (if t < self.t_off && !(t > 10.0) { self.drive(t) } else { 0.0 })
            - v[0] * self.k;
        f[1] = q[0].abs() + q[1].signum() + q[2].min(q[0]) + q[0].max(q[1])
            + q[0].hypot(q[1]) + q[1].atan2(q[2])
            - v[1]
                * (q[0].sinh() + q[1].cosh() + q[2].tanh() + (s1 + 1.0).ln()
                    + (s3 + 2.0).log10() + q[2].exp());
        f[2] = s2 + q[0].powi(-2) + (1.0 + s3).powf(1.5) + (1.0 + q[2].powi(2)).sqrt()
            - v[2] + zeitner::scalar::consts::PI + LENGTH;
        g[(0, 0)] = 2.0 * q[0];
        g[(0, 1)] = 2.0 * q[1];
        g[(1, 2)] = 1.0;
        b[0] = LENGTH.powi(2) * (0.1 * (2.0 * (2.0 * (2.0 * t).sin())))
            + v[0] * (2.0 * v[0]) + v[1] * (2.0 * v[1]);
        b[1] = -1.0 + -0.5 * v[2];
        (::zeitner::__private::FullMass(m), f, g, b)
    }
    #[inline]
    fn force_jacobians(
        &self,
        q: &::zeitner::__private::Vector<3>,
        v: &::zeitner::__private::Vector<3>,
        t: ::zeitner::__private::Float,
    ) -> (::zeitner::__private::Matrix<3, 3>, ::zeitner::__private::Matrix<3, 3>) {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let s0 = q[2].tanh();
        let s1 = q[0].powi(2) + 1.0;
        let s2 = q[1].powi(2);
        let s3 = s2 + 2.0;
        let s4 = q[2].exp();
        let s5 = q[0].hypot(q[1]);
        let s6 = 1.0 + s2;
        let s7 = q[2].powi(2);
        let s8 = 1.0 + s7;
        let s9 = 2.0 * q[1];
        let s10 = q[0].cos();
        let s11 = s2 + s7;
        let mut dq = ::zeitner::__private::Matrix::<3, 3>::zeros();
        let mut dv = ::zeitner::__private::Matrix::<3, 3>::zeros();
        dq[(0, 0)] = q[1].cos() * s10
            + 0.1 * (1.0 / (1.0 - (0.1 * q[0]).powi(2)).sqrt());
        dq[(0, 1)] = -(q[0].sin() * q[1].sin())
            - 0.1 * (1.0 / (1.0 - (0.1 * q[1]).powi(2)).sqrt());
        dq[(0, 2)] = 0.1 * (1.0 + q[2].tan().powi(2)) + 1.0 / s8;
        dq[(1, 0)] = q[0].signum() + (if q[2] <= q[0] { 0.0 } else { 1.0 })
            + (if q[0] >= q[1] { 1.0 } else { 0.0 }) + q[0] / s5
            - v[1] * (q[0].cosh() + 2.0 * q[0] * (1.0 / s1));
        dq[(1, 1)] = (if q[0] >= q[1] { 0.0 } else { 1.0 }) + q[1] / s5 + q[2] / s11
            - v[1] * (q[1].sinh() + s9 * (1.0 / (2.302585092994046 * s3)));
        dq[(1, 2)] = (if q[2] <= q[0] { 1.0 } else { 0.0 }) - q[1] / s11
            - v[1] * (s4 + 1.0 - s0.powi(2));
        dq[(2, 0)] = s10 + -2.0 * q[0].powi(-3);
        dq[(2, 1)] = s6.powf(1.5) * (if s9 == 0.0 { 0.0 } else { s9 * (1.5 / s6) });
        dq[(2, 2)] = 2.0 * q[2] * (1.0 / (2.0 * s8.sqrt()));
        dv[(0, 0)] = -self.k;
        dv[(1, 1)] = -(q[0].sinh() + q[1].cosh() + s0 + s1.ln() + s3.log10() + s4);
        dv[(2, 2)] = -1.0;
        (dq, dv)
    }
    #[inline]
    fn constraint_force_jacobians(
        &self,
        q: &::zeitner::__private::Vector<3>,
        v: &::zeitner::__private::Vector<3>,
        t: ::zeitner::__private::Float,
        lambda: &::zeitner::__private::Vector<2>,
    ) -> (::zeitner::__private::Matrix<3, 3>, ::zeitner::__private::Matrix<3, 3>) {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let s0 = 2.0 * lambda[0];
        let mut dq = ::zeitner::__private::Matrix::<3, 3>::zeros();
        let mut dv = ::zeitner::__private::Matrix::<3, 3>::zeros();
        dq[(0, 0)] = s0;
        dq[(1, 1)] = s0;
        (dq, dv)
    }
    #[inline]
    fn mass_jacobian_product(
        &self,
        q: &::zeitner::__private::Vector<3>,
        t: ::zeitner::__private::Float,
        a: &::zeitner::__private::Vector<3>,
    ) -> ::zeitner::__private::Matrix<3, 3> {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let s0 = 0.1 * q[2].sin();
        let mut dq = ::zeitner::__private::Matrix::<3, 3>::zeros();
        dq[(0, 0)] = 2.0 * q[0] * a[0];
        dq[(0, 2)] = -(a[1] * s0);
        dq[(1, 2)] = -(a[0] * s0);
        dq
    }
    #[inline]
    fn constraint_jacobian_nonzeros(
        &self,
        q: &::zeitner::__private::Vector<3>,
        v: &::zeitner::__private::Vector<3>,
        t: ::zeitner::__private::Float,
        values: &mut [::zeitner::__private::Float],
    ) {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        values[0] = 2.0 * q[0];
        values[1] = 2.0 * q[1];
        values[2] = 1.0;
    }
    #[inline]
    fn force_jacobian_nonzeros(
        &self,
        q: &::zeitner::__private::Vector<3>,
        v: &::zeitner::__private::Vector<3>,
        t: ::zeitner::__private::Float,
        values: &mut [::zeitner::__private::Float],
    ) {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let s0 = q[2].tanh();
        let s1 = q[0].powi(2) + 1.0;
        let s2 = q[1].powi(2);
        let s3 = s2 + 2.0;
        let s4 = q[2].exp();
        let s5 = q[0].hypot(q[1]);
        let s6 = 1.0 + s2;
        let s7 = q[2].powi(2);
        let s8 = 1.0 + s7;
        let s9 = 2.0 * q[1];
        let s10 = q[0].cos();
        let s11 = s2 + s7;
        values[0] = q[1].cos() * s10 + 0.1 * (1.0 / (1.0 - (0.1 * q[0]).powi(2)).sqrt());
        values[1] = -(q[0].sin() * q[1].sin())
            - 0.1 * (1.0 / (1.0 - (0.1 * q[1]).powi(2)).sqrt());
        values[2] = 0.1 * (1.0 + q[2].tan().powi(2)) + 1.0 / s8;
        values[3] = q[0].signum() + (if q[2] <= q[0] { 0.0 } else { 1.0 })
            + (if q[0] >= q[1] { 1.0 } else { 0.0 }) + q[0] / s5
            - v[1] * (q[0].cosh() + 2.0 * q[0] * (1.0 / s1));
        values[4] = (if q[0] >= q[1] { 0.0 } else { 1.0 }) + q[1] / s5 + q[2] / s11
            - v[1] * (q[1].sinh() + s9 * (1.0 / (2.302585092994046 * s3)));
        values[5] = (if q[2] <= q[0] { 1.0 } else { 0.0 }) - q[1] / s11
            - v[1] * (s4 + 1.0 - s0.powi(2));
        values[6] = s10 + -2.0 * q[0].powi(-3);
        values[7] = s6.powf(1.5) * (if s9 == 0.0 { 0.0 } else { s9 * (1.5 / s6) });
        values[8] = 2.0 * q[2] * (1.0 / (2.0 * s8.sqrt()));
        values[9] = -self.k;
        values[10] = -(q[0].sinh() + q[1].cosh() + s0 + s1.ln() + s3.log10() + s4);
        values[11] = -1.0;
    }
    #[inline]
    fn constraint_force_jacobian_nonzeros(
        &self,
        q: &::zeitner::__private::Vector<3>,
        v: &::zeitner::__private::Vector<3>,
        t: ::zeitner::__private::Float,
        lambda: &::zeitner::__private::Vector<2>,
        values: &mut [::zeitner::__private::Float],
    ) {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let s0 = 2.0 * lambda[0];
        values[0] = s0;
        values[1] = s0;
    }
}
