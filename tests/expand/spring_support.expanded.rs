#[allow(dead_code)]
impl SpringSupportedPendulum {
    fn mass(&self) -> [Float; 4] {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        [self.support, self.support, self.m, self.m]
    }
    fn force(
        &self,
        [xs,
        ys,
        _xb,
        _yb,
        ]: [Float; 4],
        [us,
        ws,
        _ub,
        _wb,
        ]: [Float; 4],
    ) -> [Float; 4] {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        [
            -self.k * xs - self.c * us,
            -self.k * ys - self.c * ws - self.support * self.g,
            0.0,
            -self.m * self.g,
        ]
    }
    fn constraints(&self, [xs, ys, xb, yb]: [Float; 4]) -> [Float; 1] {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        [(xb - xs).powi(2) + (yb - ys).powi(2) - self.l * self.l]
    }
    fn parameters(&self) -> [Float; 2] {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        [self.k, self.c]
    }
}
#[allow(unused_variables, unused_mut, clippy::all)]
impl ::zeitner::__private::ConstrainedSystem<4, 1> for SpringSupportedPendulum {
    const POSITION_CONSTRAINTS: usize = 1;
    const MASS_IS_CONSTANT: bool = true;
    const DYNAMICS_DEPEND_ON_VELOCITY: bool = true;
    const SUMMARY: ::zeitner::__private::SceneSummary = ::zeitner::__private::SceneSummary {
        coordinates: 4,
        position_constraints: 1,
        velocity_constraints: 0,
        mass: ::zeitner::__private::MassKind::ConstantDiagonal,
        time_dependent: false,
        functions: &[
            ::zeitner::__private::FunctionSummary {
                name: "mass_matrix",
                blocks: &[
                    ::zeitner::__private::BlockSummary {
                        name: "m",
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
                name: "applied_force",
                blocks: &[
                    ::zeitner::__private::BlockSummary {
                        name: "f",
                        rows: 4,
                        cols: 1,
                        nonzeros: &[(0, 0), (1, 0), (3, 0)],
                    },
                ],
                ops: ::zeitner::__private::OpCounts {
                    adds: 6u64,
                    muls: 6u64,
                    divs: 0u64,
                    transcendental: 0u64,
                    opaque_calls: 0u64,
                },
                ops_unshared: ::zeitner::__private::OpCounts {
                    adds: 6u64,
                    muls: 6u64,
                    divs: 0u64,
                    transcendental: 0u64,
                    opaque_calls: 0u64,
                },
            },
            ::zeitner::__private::FunctionSummary {
                name: "constraint_residual",
                blocks: &[
                    ::zeitner::__private::BlockSummary {
                        name: "g",
                        rows: 1,
                        cols: 1,
                        nonzeros: &[(0, 0)],
                    },
                ],
                ops: ::zeitner::__private::OpCounts {
                    adds: 4u64,
                    muls: 3u64,
                    divs: 0u64,
                    transcendental: 0u64,
                    opaque_calls: 0u64,
                },
                ops_unshared: ::zeitner::__private::OpCounts {
                    adds: 4u64,
                    muls: 3u64,
                    divs: 0u64,
                    transcendental: 0u64,
                    opaque_calls: 0u64,
                },
            },
            ::zeitner::__private::FunctionSummary {
                name: "constraint_jacobian",
                blocks: &[
                    ::zeitner::__private::BlockSummary {
                        name: "g",
                        rows: 1,
                        cols: 4,
                        nonzeros: &[(0, 0), (0, 1), (0, 2), (0, 3)],
                    },
                ],
                ops: ::zeitner::__private::OpCounts {
                    adds: 4u64,
                    muls: 2u64,
                    divs: 0u64,
                    transcendental: 0u64,
                    opaque_calls: 0u64,
                },
                ops_unshared: ::zeitner::__private::OpCounts {
                    adds: 6u64,
                    muls: 4u64,
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
                        rows: 1,
                        cols: 1,
                        nonzeros: &[(0, 0)],
                    },
                ],
                ops: ::zeitner::__private::OpCounts {
                    adds: 6u64,
                    muls: 6u64,
                    divs: 0u64,
                    transcendental: 0u64,
                    opaque_calls: 0u64,
                },
                ops_unshared: ::zeitner::__private::OpCounts {
                    adds: 8u64,
                    muls: 8u64,
                    divs: 0u64,
                    transcendental: 0u64,
                    opaque_calls: 0u64,
                },
            },
            ::zeitner::__private::FunctionSummary {
                name: "constraint_acceleration_bias",
                blocks: &[
                    ::zeitner::__private::BlockSummary {
                        name: "b",
                        rows: 1,
                        cols: 1,
                        nonzeros: &[(0, 0)],
                    },
                ],
                ops: ::zeitner::__private::OpCounts {
                    adds: 7u64,
                    muls: 12u64,
                    divs: 0u64,
                    transcendental: 0u64,
                    opaque_calls: 0u64,
                },
                ops_unshared: ::zeitner::__private::OpCounts {
                    adds: 7u64,
                    muls: 12u64,
                    divs: 0u64,
                    transcendental: 0u64,
                    opaque_calls: 0u64,
                },
            },
            ::zeitner::__private::FunctionSummary {
                name: "stage",
                blocks: &[
                    ::zeitner::__private::BlockSummary {
                        name: "m",
                        rows: 4,
                        cols: 1,
                        nonzeros: &[(0, 0), (1, 0), (2, 0), (3, 0)],
                    },
                    ::zeitner::__private::BlockSummary {
                        name: "f",
                        rows: 4,
                        cols: 1,
                        nonzeros: &[(0, 0), (1, 0), (3, 0)],
                    },
                    ::zeitner::__private::BlockSummary {
                        name: "g",
                        rows: 1,
                        cols: 4,
                        nonzeros: &[(0, 0), (0, 1), (0, 2), (0, 3)],
                    },
                    ::zeitner::__private::BlockSummary {
                        name: "b",
                        rows: 1,
                        cols: 1,
                        nonzeros: &[(0, 0)],
                    },
                ],
                ops: ::zeitner::__private::OpCounts {
                    adds: 17u64,
                    muls: 20u64,
                    divs: 0u64,
                    transcendental: 0u64,
                    opaque_calls: 0u64,
                },
                ops_unshared: ::zeitner::__private::OpCounts {
                    adds: 19u64,
                    muls: 22u64,
                    divs: 0u64,
                    transcendental: 0u64,
                    opaque_calls: 0u64,
                },
            },
            ::zeitner::__private::FunctionSummary {
                name: "force_jacobians",
                blocks: &[
                    ::zeitner::__private::BlockSummary {
                        name: "dq",
                        rows: 4,
                        cols: 4,
                        nonzeros: &[(0, 0), (1, 1)],
                    },
                    ::zeitner::__private::BlockSummary {
                        name: "dv",
                        rows: 4,
                        cols: 4,
                        nonzeros: &[(0, 0), (1, 1)],
                    },
                ],
                ops: ::zeitner::__private::OpCounts {
                    adds: 2u64,
                    muls: 0u64,
                    divs: 0u64,
                    transcendental: 0u64,
                    opaque_calls: 0u64,
                },
                ops_unshared: ::zeitner::__private::OpCounts {
                    adds: 4u64,
                    muls: 0u64,
                    divs: 0u64,
                    transcendental: 0u64,
                    opaque_calls: 0u64,
                },
            },
            ::zeitner::__private::FunctionSummary {
                name: "constraint_force_jacobians",
                blocks: &[
                    ::zeitner::__private::BlockSummary {
                        name: "dq",
                        rows: 4,
                        cols: 4,
                        nonzeros: &[
                            (0, 0),
                            (0, 2),
                            (1, 1),
                            (1, 3),
                            (2, 0),
                            (2, 2),
                            (3, 1),
                            (3, 3),
                        ],
                    },
                    ::zeitner::__private::BlockSummary {
                        name: "dv",
                        rows: 4,
                        cols: 4,
                        nonzeros: &[],
                    },
                ],
                ops: ::zeitner::__private::OpCounts {
                    adds: 2u64,
                    muls: 2u64,
                    divs: 0u64,
                    transcendental: 0u64,
                    opaque_calls: 0u64,
                },
                ops_unshared: ::zeitner::__private::OpCounts {
                    adds: 4u64,
                    muls: 8u64,
                    divs: 0u64,
                    transcendental: 0u64,
                    opaque_calls: 0u64,
                },
            },
            ::zeitner::__private::FunctionSummary {
                name: "rate_jacobians",
                blocks: &[
                    ::zeitner::__private::BlockSummary {
                        name: "wq",
                        rows: 1,
                        cols: 4,
                        nonzeros: &[(0, 0), (0, 1), (0, 2), (0, 3)],
                    },
                    ::zeitner::__private::BlockSummary {
                        name: "wv",
                        rows: 1,
                        cols: 4,
                        nonzeros: &[(0, 0), (0, 1), (0, 2), (0, 3)],
                    },
                ],
                ops: ::zeitner::__private::OpCounts {
                    adds: 8u64,
                    muls: 10u64,
                    divs: 0u64,
                    transcendental: 0u64,
                    opaque_calls: 0u64,
                },
                ops_unshared: ::zeitner::__private::OpCounts {
                    adds: 10u64,
                    muls: 12u64,
                    divs: 0u64,
                    transcendental: 0u64,
                    opaque_calls: 0u64,
                },
            },
            ::zeitner::__private::FunctionSummary {
                name: "acceleration_constraint_jacobians",
                blocks: &[
                    ::zeitner::__private::BlockSummary {
                        name: "cq",
                        rows: 1,
                        cols: 4,
                        nonzeros: &[(0, 0), (0, 1), (0, 2), (0, 3)],
                    },
                    ::zeitner::__private::BlockSummary {
                        name: "cv",
                        rows: 1,
                        cols: 4,
                        nonzeros: &[(0, 0), (0, 1), (0, 2), (0, 3)],
                    },
                    ::zeitner::__private::BlockSummary {
                        name: "cp",
                        rows: 1,
                        cols: 2,
                        nonzeros: &[],
                    },
                ],
                ops: ::zeitner::__private::OpCounts {
                    adds: 16u64,
                    muls: 16u64,
                    divs: 0u64,
                    transcendental: 0u64,
                    opaque_calls: 0u64,
                },
                ops_unshared: ::zeitner::__private::OpCounts {
                    adds: 16u64,
                    muls: 24u64,
                    divs: 0u64,
                    transcendental: 0u64,
                    opaque_calls: 0u64,
                },
            },
            ::zeitner::__private::FunctionSummary {
                name: "parameter_values",
                blocks: &[
                    ::zeitner::__private::BlockSummary {
                        name: "theta",
                        rows: 2,
                        cols: 1,
                        nonzeros: &[(0, 0), (1, 0)],
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
                        rows: 4,
                        cols: 2,
                        nonzeros: &[(0, 0), (0, 1), (1, 0), (1, 1)],
                    },
                ],
                ops: ::zeitner::__private::OpCounts {
                    adds: 4u64,
                    muls: 0u64,
                    divs: 0u64,
                    transcendental: 0u64,
                    opaque_calls: 0u64,
                },
                ops_unshared: ::zeitner::__private::OpCounts {
                    adds: 4u64,
                    muls: 0u64,
                    divs: 0u64,
                    transcendental: 0u64,
                    opaque_calls: 0u64,
                },
            },
            ::zeitner::__private::FunctionSummary {
                name: "parameter_constraints",
                blocks: &[
                    ::zeitner::__private::BlockSummary {
                        name: "dg",
                        rows: 1,
                        cols: 2,
                        nonzeros: &[],
                    },
                    ::zeitner::__private::BlockSummary {
                        name: "dw",
                        rows: 1,
                        cols: 2,
                        nonzeros: &[],
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
        ],
    };
    type Mass = ::zeitner::__private::DiagonalMass<4>;
    type Storage = ::zeitner::__private::Dense;
    const SPARSITY: ::core::option::Option<::zeitner::__private::Sparsity> = ::core::option::Option::Some(::zeitner::__private::Sparsity {
        constraint_jacobian: &[(0, 0), (0, 1), (0, 2), (0, 3)],
        force_jacobians: [&[(0, 0), (1, 1)], &[(0, 0), (1, 1)]],
        constraint_force_jacobians: [
            &[(0, 0), (0, 2), (1, 1), (1, 3), (2, 0), (2, 2), (3, 1), (3, 3)],
            &[],
        ],
    });
    #[inline]
    fn mass_matrix(
        &self,
        q: &::zeitner::__private::Vector<4>,
        t: ::zeitner::__private::Float,
    ) -> Self::Mass {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let mut m = ::zeitner::__private::Vector::<4>::zeros();
        m[0] = self.support;
        m[1] = self.support;
        m[2] = self.m;
        m[3] = self.m;
        ::zeitner::__private::DiagonalMass(m)
    }
    #[inline]
    fn applied_force(
        &self,
        q: &::zeitner::__private::Vector<4>,
        v: &::zeitner::__private::Vector<4>,
        t: ::zeitner::__private::Float,
    ) -> ::zeitner::__private::Vector<4> {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let mut f = ::zeitner::__private::Vector::<4>::zeros();
        f[0] = -(q[0] * self.k) - v[0] * self.c;
        f[1] = -(q[1] * self.k) - v[1] * self.c - self.support * self.g;
        f[3] = -(self.m * self.g);
        f
    }
    #[inline]
    fn constraint_residual(
        &self,
        q: &::zeitner::__private::Vector<4>,
        v: &::zeitner::__private::Vector<4>,
        t: ::zeitner::__private::Float,
    ) -> ::zeitner::__private::Vector<1> {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let mut g = ::zeitner::__private::Vector::<1>::zeros();
        g[0] = (q[2] - q[0]).powi(2) + (q[3] - q[1]).powi(2) - self.l.powi(2);
        g
    }
    #[inline]
    fn constraint_jacobian(
        &self,
        q: &::zeitner::__private::Vector<4>,
        v: &::zeitner::__private::Vector<4>,
        t: ::zeitner::__private::Float,
    ) -> ::zeitner::__private::Matrix<1, 4> {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let s0 = 2.0 * (q[2] - q[0]);
        let s1 = 2.0 * (q[3] - q[1]);
        let mut g = ::zeitner::__private::Matrix::<1, 4>::zeros();
        g[(0, 0)] = -s0;
        g[(0, 1)] = -s1;
        g[(0, 2)] = s0;
        g[(0, 3)] = s1;
        g
    }
    #[inline]
    fn constraint_rate(
        &self,
        q: &::zeitner::__private::Vector<4>,
        v: &::zeitner::__private::Vector<4>,
        t: ::zeitner::__private::Float,
    ) -> ::zeitner::__private::Vector<1> {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let s0 = 2.0 * (q[2] - q[0]);
        let s1 = 2.0 * (q[3] - q[1]);
        let mut w = ::zeitner::__private::Vector::<1>::zeros();
        w[0] = -(v[0] * s0) - v[1] * s1 + v[2] * s0 + v[3] * s1;
        w
    }
    #[inline]
    fn constraint_acceleration_bias(
        &self,
        q: &::zeitner::__private::Vector<4>,
        v: &::zeitner::__private::Vector<4>,
        t: ::zeitner::__private::Float,
    ) -> ::zeitner::__private::Vector<1> {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let mut b = ::zeitner::__private::Vector::<1>::zeros();
        b[0] = v[0] * (-2.0 * v[2] - -2.0 * v[0]) + v[1] * (-2.0 * v[3] - -2.0 * v[1])
            + v[2] * (2.0 * v[2] - 2.0 * v[0]) + v[3] * (2.0 * v[3] - 2.0 * v[1]);
        b
    }
    #[inline]
    fn stage(
        &self,
        q: &::zeitner::__private::Vector<4>,
        v: &::zeitner::__private::Vector<4>,
        t: ::zeitner::__private::Float,
    ) -> (
        Self::Mass,
        ::zeitner::__private::Vector<4>,
        ::zeitner::__private::Matrix<1, 4>,
        ::zeitner::__private::Vector<1>,
    ) {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let s0 = 2.0 * (q[2] - q[0]);
        let s1 = 2.0 * (q[3] - q[1]);
        let mut m = ::zeitner::__private::Vector::<4>::zeros();
        let mut f = ::zeitner::__private::Vector::<4>::zeros();
        let mut g = ::zeitner::__private::Matrix::<1, 4>::zeros();
        let mut b = ::zeitner::__private::Vector::<1>::zeros();
        m[0] = self.support;
        m[1] = self.support;
        m[2] = self.m;
        m[3] = self.m;
        f[0] = -(q[0] * self.k) - v[0] * self.c;
        f[1] = -(q[1] * self.k) - v[1] * self.c - self.support * self.g;
        f[3] = -(self.m * self.g);
        g[(0, 0)] = -s0;
        g[(0, 1)] = -s1;
        g[(0, 2)] = s0;
        g[(0, 3)] = s1;
        b[0] = v[0] * (-2.0 * v[2] - -2.0 * v[0]) + v[1] * (-2.0 * v[3] - -2.0 * v[1])
            + v[2] * (2.0 * v[2] - 2.0 * v[0]) + v[3] * (2.0 * v[3] - 2.0 * v[1]);
        (::zeitner::__private::DiagonalMass(m), f, g, b)
    }
    #[inline]
    fn force_jacobians(
        &self,
        q: &::zeitner::__private::Vector<4>,
        v: &::zeitner::__private::Vector<4>,
        t: ::zeitner::__private::Float,
    ) -> (::zeitner::__private::Matrix<4, 4>, ::zeitner::__private::Matrix<4, 4>) {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let s0 = -self.k;
        let s1 = -self.c;
        let mut dq = ::zeitner::__private::Matrix::<4, 4>::zeros();
        let mut dv = ::zeitner::__private::Matrix::<4, 4>::zeros();
        dq[(0, 0)] = s0;
        dq[(1, 1)] = s0;
        dv[(0, 0)] = s1;
        dv[(1, 1)] = s1;
        (dq, dv)
    }
    #[inline]
    fn constraint_force_jacobians(
        &self,
        q: &::zeitner::__private::Vector<4>,
        v: &::zeitner::__private::Vector<4>,
        t: ::zeitner::__private::Float,
        lambda: &::zeitner::__private::Vector<1>,
    ) -> (::zeitner::__private::Matrix<4, 4>, ::zeitner::__private::Matrix<4, 4>) {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let s0 = -2.0 * lambda[0];
        let s1 = -s0;
        let s2 = 2.0 * lambda[0];
        let s3 = -s2;
        let mut dq = ::zeitner::__private::Matrix::<4, 4>::zeros();
        let mut dv = ::zeitner::__private::Matrix::<4, 4>::zeros();
        dq[(0, 0)] = s1;
        dq[(0, 2)] = s3;
        dq[(1, 1)] = s1;
        dq[(1, 3)] = s3;
        dq[(2, 0)] = s0;
        dq[(2, 2)] = s2;
        dq[(3, 1)] = s0;
        dq[(3, 3)] = s2;
        (dq, dv)
    }
    #[inline]
    fn constraint_jacobian_nonzeros(
        &self,
        q: &::zeitner::__private::Vector<4>,
        v: &::zeitner::__private::Vector<4>,
        t: ::zeitner::__private::Float,
        values: &mut [::zeitner::__private::Float],
    ) {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let s0 = 2.0 * (q[2] - q[0]);
        let s1 = 2.0 * (q[3] - q[1]);
        values[0] = -s0;
        values[1] = -s1;
        values[2] = s0;
        values[3] = s1;
    }
    #[inline]
    fn force_jacobian_nonzeros(
        &self,
        q: &::zeitner::__private::Vector<4>,
        v: &::zeitner::__private::Vector<4>,
        t: ::zeitner::__private::Float,
        values: &mut [::zeitner::__private::Float],
    ) {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let s0 = -self.k;
        let s1 = -self.c;
        values[0] = s0;
        values[1] = s0;
        values[2] = s1;
        values[3] = s1;
    }
    #[inline]
    fn constraint_force_jacobian_nonzeros(
        &self,
        q: &::zeitner::__private::Vector<4>,
        v: &::zeitner::__private::Vector<4>,
        t: ::zeitner::__private::Float,
        lambda: &::zeitner::__private::Vector<1>,
        values: &mut [::zeitner::__private::Float],
    ) {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let s0 = -2.0 * lambda[0];
        let s1 = -s0;
        let s2 = 2.0 * lambda[0];
        let s3 = -s2;
        values[0] = s1;
        values[1] = s3;
        values[2] = s1;
        values[3] = s3;
        values[4] = s0;
        values[5] = s2;
        values[6] = s0;
        values[7] = s2;
    }
}
#[allow(unused_variables, unused_mut, clippy::all)]
impl ::zeitner::__private::ParametrisedSystem<4, 1, 2> for SpringSupportedPendulum {
    const PARAMETER_NAMES: [&'static str; 2] = ["k", "c"];
    #[inline]
    fn parameter_values(&self) -> ::zeitner::__private::Vector<2> {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let mut theta = ::zeitner::__private::Vector::<2>::zeros();
        theta[0] = self.k;
        theta[1] = self.c;
        theta
    }
    #[inline]
    fn parameter_force(
        &self,
        q: &::zeitner::__private::Vector<4>,
        v: &::zeitner::__private::Vector<4>,
        t: ::zeitner::__private::Float,
        lambda: &::zeitner::__private::Vector<1>,
        a: &::zeitner::__private::Vector<4>,
    ) -> ::zeitner::__private::Matrix<4, 2> {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let mut df = ::zeitner::__private::Matrix::<4, 2>::zeros();
        df[(0, 0)] = -q[0];
        df[(0, 1)] = -v[0];
        df[(1, 0)] = -q[1];
        df[(1, 1)] = -v[1];
        df
    }
    #[inline]
    fn parameter_constraints(
        &self,
        q: &::zeitner::__private::Vector<4>,
        v: &::zeitner::__private::Vector<4>,
        t: ::zeitner::__private::Float,
    ) -> (::zeitner::__private::Matrix<1, 2>, ::zeitner::__private::Matrix<1, 2>) {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let mut dg = ::zeitner::__private::Matrix::<1, 2>::zeros();
        let mut dw = ::zeitner::__private::Matrix::<1, 2>::zeros();
        (dg, dw)
    }
    #[inline]
    fn rate_jacobians(
        &self,
        q: &::zeitner::__private::Vector<4>,
        v: &::zeitner::__private::Vector<4>,
        t: ::zeitner::__private::Float,
    ) -> (::zeitner::__private::Matrix<1, 4>, ::zeitner::__private::Matrix<1, 4>) {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let s0 = 2.0 * (q[2] - q[0]);
        let s1 = 2.0 * (q[3] - q[1]);
        let mut wq = ::zeitner::__private::Matrix::<1, 4>::zeros();
        let mut wv = ::zeitner::__private::Matrix::<1, 4>::zeros();
        wq[(0, 0)] = -2.0 * v[2] - -2.0 * v[0];
        wq[(0, 1)] = -2.0 * v[3] - -2.0 * v[1];
        wq[(0, 2)] = 2.0 * v[2] - 2.0 * v[0];
        wq[(0, 3)] = 2.0 * v[3] - 2.0 * v[1];
        wv[(0, 0)] = -s0;
        wv[(0, 1)] = -s1;
        wv[(0, 2)] = s0;
        wv[(0, 3)] = s1;
        (wq, wv)
    }
    #[inline]
    fn acceleration_constraint_jacobians(
        &self,
        q: &::zeitner::__private::Vector<4>,
        v: &::zeitner::__private::Vector<4>,
        t: ::zeitner::__private::Float,
        a: &::zeitner::__private::Vector<4>,
    ) -> (
        ::zeitner::__private::Matrix<1, 4>,
        ::zeitner::__private::Matrix<1, 4>,
        ::zeitner::__private::Matrix<1, 2>,
    ) {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let s0 = -2.0 * v[0];
        let s1 = -2.0 * v[2];
        let s2 = -2.0 * v[1];
        let s3 = -2.0 * v[3];
        let s4 = 2.0 * v[0];
        let s5 = 2.0 * v[2];
        let s6 = 2.0 * v[1];
        let s7 = 2.0 * v[3];
        let mut cq = ::zeitner::__private::Matrix::<1, 4>::zeros();
        let mut cv = ::zeitner::__private::Matrix::<1, 4>::zeros();
        let mut cp = ::zeitner::__private::Matrix::<1, 2>::zeros();
        cq[(0, 0)] = -2.0 * a[2] - -2.0 * a[0];
        cq[(0, 1)] = -2.0 * a[3] - -2.0 * a[1];
        cq[(0, 2)] = 2.0 * a[2] - 2.0 * a[0];
        cq[(0, 3)] = 2.0 * a[3] - 2.0 * a[1];
        cv[(0, 0)] = s1 + s1 - s0 + s4;
        cv[(0, 1)] = s3 + s3 - s2 + s6;
        cv[(0, 2)] = s0 + s5 + s5 - s4;
        cv[(0, 3)] = s2 + s7 + s7 - s6;
        (cq, cv, cp)
    }
}
