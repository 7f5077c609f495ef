#[allow(dead_code)]
impl SliderCrankOnAxis {
    fn mass(&self) -> [Float; 4] {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        [self.m, self.m, self.ms, self.ms]
    }
    fn force(&self) -> [Float; 4] {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        [0.0, -self.m * self.g, 0.0, -self.ms * self.g]
    }
    fn constraints(&self, [x1, y1, x2, y2]: [Float; 4]) -> [Float; 3] {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        [
            x1 * x1 + y1 * y1 - self.r * self.r,
            (x2 - x1) * (x2 - x1) + (y2 - y1) * (y2 - y1) - self.l * self.l,
            y2,
        ]
    }
    fn events(&self, [_x1, y1, _x2, _y2]: [Float; 4]) -> [Float; 1] {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        [y1]
    }
}
#[allow(unused_variables, unused_mut, clippy::all)]
impl ::zeitner::__private::ConstrainedSystem<4, 3> for SliderCrankOnAxis {
    const POSITION_CONSTRAINTS: usize = 3;
    const MASS_IS_CONSTANT: bool = true;
    const DYNAMICS_DEPEND_ON_VELOCITY: bool = false;
    const SUMMARY: ::zeitner::__private::SceneSummary = ::zeitner::__private::SceneSummary {
        coordinates: 4,
        position_constraints: 3,
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
                        nonzeros: &[(1, 0), (3, 0)],
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
                    adds: 2u64,
                    muls: 2u64,
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
                        rows: 3,
                        cols: 1,
                        nonzeros: &[(0, 0), (1, 0), (2, 0)],
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
                name: "constraint_jacobian",
                blocks: &[
                    ::zeitner::__private::BlockSummary {
                        name: "g",
                        rows: 3,
                        cols: 4,
                        nonzeros: &[
                            (0, 0),
                            (0, 1),
                            (1, 0),
                            (1, 1),
                            (1, 2),
                            (1, 3),
                            (2, 3),
                        ],
                    },
                ],
                ops: ::zeitner::__private::OpCounts {
                    adds: 4u64,
                    muls: 4u64,
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
                name: "constraint_rate",
                blocks: &[
                    ::zeitner::__private::BlockSummary {
                        name: "w",
                        rows: 3,
                        cols: 1,
                        nonzeros: &[(0, 0), (1, 0), (2, 0)],
                    },
                ],
                ops: ::zeitner::__private::OpCounts {
                    adds: 7u64,
                    muls: 10u64,
                    divs: 0u64,
                    transcendental: 0u64,
                    opaque_calls: 0u64,
                },
                ops_unshared: ::zeitner::__private::OpCounts {
                    adds: 9u64,
                    muls: 12u64,
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
                        rows: 3,
                        cols: 1,
                        nonzeros: &[(0, 0), (1, 0)],
                    },
                ],
                ops: ::zeitner::__private::OpCounts {
                    adds: 8u64,
                    muls: 14u64,
                    divs: 0u64,
                    transcendental: 0u64,
                    opaque_calls: 0u64,
                },
                ops_unshared: ::zeitner::__private::OpCounts {
                    adds: 8u64,
                    muls: 16u64,
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
                        nonzeros: &[(1, 0), (3, 0)],
                    },
                    ::zeitner::__private::BlockSummary {
                        name: "g",
                        rows: 3,
                        cols: 4,
                        nonzeros: &[
                            (0, 0),
                            (0, 1),
                            (1, 0),
                            (1, 1),
                            (1, 2),
                            (1, 3),
                            (2, 3),
                        ],
                    },
                    ::zeitner::__private::BlockSummary {
                        name: "b",
                        rows: 3,
                        cols: 1,
                        nonzeros: &[(0, 0), (1, 0)],
                    },
                ],
                ops: ::zeitner::__private::OpCounts {
                    adds: 14u64,
                    muls: 20u64,
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
                name: "force_jacobians",
                blocks: &[
                    ::zeitner::__private::BlockSummary {
                        name: "dq",
                        rows: 4,
                        cols: 4,
                        nonzeros: &[],
                    },
                    ::zeitner::__private::BlockSummary {
                        name: "dv",
                        rows: 4,
                        cols: 4,
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
                    muls: 3u64,
                    divs: 0u64,
                    transcendental: 0u64,
                    opaque_calls: 0u64,
                },
                ops_unshared: ::zeitner::__private::OpCounts {
                    adds: 4u64,
                    muls: 10u64,
                    divs: 0u64,
                    transcendental: 0u64,
                    opaque_calls: 0u64,
                },
            },
            ::zeitner::__private::FunctionSummary {
                name: "event_functions",
                blocks: &[
                    ::zeitner::__private::BlockSummary {
                        name: "e",
                        rows: 1,
                        cols: 1,
                        nonzeros: &[(0, 0)],
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
    const EVENTS: usize = 1usize;
    const SPARSITY: ::core::option::Option<::zeitner::__private::Sparsity> = ::core::option::Option::Some(::zeitner::__private::Sparsity {
        constraint_jacobian: &[(0, 0), (0, 1), (1, 0), (1, 1), (1, 2), (1, 3), (2, 3)],
        force_jacobians: [&[], &[]],
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
        m[0] = self.m;
        m[1] = self.m;
        m[2] = self.ms;
        m[3] = self.ms;
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
        f[1] = -(self.m * self.g);
        f[3] = -(self.ms * self.g);
        f
    }
    #[inline]
    fn constraint_residual(
        &self,
        q: &::zeitner::__private::Vector<4>,
        v: &::zeitner::__private::Vector<4>,
        t: ::zeitner::__private::Float,
    ) -> ::zeitner::__private::Vector<3> {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let mut g = ::zeitner::__private::Vector::<3>::zeros();
        g[0] = q[0].powi(2) + q[1].powi(2) - self.r.powi(2);
        g[1] = (q[2] - q[0]).powi(2) + (q[3] - q[1]).powi(2) - self.l.powi(2);
        g[2] = q[3];
        g
    }
    #[inline]
    fn constraint_jacobian(
        &self,
        q: &::zeitner::__private::Vector<4>,
        v: &::zeitner::__private::Vector<4>,
        t: ::zeitner::__private::Float,
    ) -> ::zeitner::__private::Matrix<3, 4> {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let s0 = 2.0 * (q[2] - q[0]);
        let s1 = 2.0 * (q[3] - q[1]);
        let mut g = ::zeitner::__private::Matrix::<3, 4>::zeros();
        g[(0, 0)] = 2.0 * q[0];
        g[(0, 1)] = 2.0 * q[1];
        g[(1, 0)] = -s0;
        g[(1, 1)] = -s1;
        g[(1, 2)] = s0;
        g[(1, 3)] = s1;
        g[(2, 3)] = 1.0;
        g
    }
    #[inline]
    fn constraint_rate(
        &self,
        q: &::zeitner::__private::Vector<4>,
        v: &::zeitner::__private::Vector<4>,
        t: ::zeitner::__private::Float,
    ) -> ::zeitner::__private::Vector<3> {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let s0 = 2.0 * (q[2] - q[0]);
        let s1 = 2.0 * (q[3] - q[1]);
        let mut w = ::zeitner::__private::Vector::<3>::zeros();
        w[0] = 2.0 * q[0] * v[0] + 2.0 * q[1] * v[1];
        w[1] = -(s0 * v[0]) - s1 * v[1] + s0 * v[2] + s1 * v[3];
        w[2] = v[3];
        w
    }
    #[inline]
    fn constraint_acceleration_bias(
        &self,
        q: &::zeitner::__private::Vector<4>,
        v: &::zeitner::__private::Vector<4>,
        t: ::zeitner::__private::Float,
    ) -> ::zeitner::__private::Vector<3> {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let s0 = 2.0 * v[0];
        let s1 = 2.0 * v[1];
        let mut b = ::zeitner::__private::Vector::<3>::zeros();
        b[0] = v[0] * s0 + v[1] * s1;
        b[1] = v[0] * (-2.0 * v[2] - -2.0 * v[0]) + v[1] * (-2.0 * v[3] - -2.0 * v[1])
            + v[2] * (2.0 * v[2] - s0) + v[3] * (2.0 * v[3] - s1);
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
        ::zeitner::__private::Matrix<3, 4>,
        ::zeitner::__private::Vector<3>,
    ) {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let s0 = 2.0 * (q[2] - q[0]);
        let s1 = 2.0 * (q[3] - q[1]);
        let s2 = 2.0 * v[0];
        let s3 = 2.0 * v[1];
        let mut m = ::zeitner::__private::Vector::<4>::zeros();
        let mut f = ::zeitner::__private::Vector::<4>::zeros();
        let mut g = ::zeitner::__private::Matrix::<3, 4>::zeros();
        let mut b = ::zeitner::__private::Vector::<3>::zeros();
        m[0] = self.m;
        m[1] = self.m;
        m[2] = self.ms;
        m[3] = self.ms;
        f[1] = -(self.m * self.g);
        f[3] = -(self.ms * self.g);
        g[(0, 0)] = 2.0 * q[0];
        g[(0, 1)] = 2.0 * q[1];
        g[(1, 0)] = -s0;
        g[(1, 1)] = -s1;
        g[(1, 2)] = s0;
        g[(1, 3)] = s1;
        g[(2, 3)] = 1.0;
        b[0] = v[0] * s2 + v[1] * s3;
        b[1] = v[0] * (-2.0 * v[2] - -2.0 * v[0]) + v[1] * (-2.0 * v[3] - -2.0 * v[1])
            + v[2] * (2.0 * v[2] - s2) + v[3] * (2.0 * v[3] - s3);
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
        let mut dq = ::zeitner::__private::Matrix::<4, 4>::zeros();
        let mut dv = ::zeitner::__private::Matrix::<4, 4>::zeros();
        (dq, dv)
    }
    #[inline]
    fn constraint_force_jacobians(
        &self,
        q: &::zeitner::__private::Vector<4>,
        v: &::zeitner::__private::Vector<4>,
        t: ::zeitner::__private::Float,
        lambda: &::zeitner::__private::Vector<3>,
    ) -> (::zeitner::__private::Matrix<4, 4>, ::zeitner::__private::Matrix<4, 4>) {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let s0 = -2.0 * lambda[1];
        let s1 = 2.0 * lambda[0] - s0;
        let s2 = 2.0 * lambda[1];
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
    fn event_functions(
        &self,
        q: &::zeitner::__private::Vector<4>,
        v: &::zeitner::__private::Vector<4>,
        t: ::zeitner::__private::Float,
        values: &mut [::zeitner::__private::Float],
    ) {
        let e = {
            #[allow(unused_imports)]
            use ::zeitner::__private::Real as _;
            let mut e = ::zeitner::__private::Vector::<1>::zeros();
            e[0] = q[1];
            e
        };
        for (value, x) in values.iter_mut().zip(e.iter()) {
            *value = *x;
        }
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
        values[0] = 2.0 * q[0];
        values[1] = 2.0 * q[1];
        values[2] = -s0;
        values[3] = -s1;
        values[4] = s0;
        values[5] = s1;
        values[6] = 1.0;
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
    }
    #[inline]
    fn constraint_force_jacobian_nonzeros(
        &self,
        q: &::zeitner::__private::Vector<4>,
        v: &::zeitner::__private::Vector<4>,
        t: ::zeitner::__private::Float,
        lambda: &::zeitner::__private::Vector<3>,
        values: &mut [::zeitner::__private::Float],
    ) {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let s0 = -2.0 * lambda[1];
        let s1 = 2.0 * lambda[0] - s0;
        let s2 = 2.0 * lambda[1];
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
