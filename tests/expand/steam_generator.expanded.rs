#[allow(dead_code)]
impl SteamGenerator {
    fn mass(&self) -> [Float; 3] {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        [self.m, self.m, self.j]
    }
    fn force(
        &self,
        [_q1,
        _q2,
        _q3,
        ]: [Float; 3],
        [v1,
        _v2,
        _v3,
        ]: [Float; 3],
        t: Float,
    ) -> [Float; 3] {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let p = self.load(t);
        [p - self.d * v1, -self.m * self.g, p * self.h1]
    }
    fn constraints(&self, [q1, q2, q3]: [Float; 3]) -> [Float; 2] {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        [q1 - self.h3 * q3, q1 * q1 + (q2 - self.h2).powi(2) - self.h2 * self.h2]
    }
    /// The load's kink at the end of its ramp and its switch-off: steps land on them.
    fn time_events(&self) -> [Float; 2] {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        [self.rise, self.off]
    }
    /// The supports' geometry and the damper, for sensitivities (the load's `p0` and `rise`
    /// are read in `load`, an opaque method, so they cannot be parameters).
    fn parameters(&self) -> [Float; 4] {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        [self.h3, self.h2, self.d, self.m]
    }
}
#[allow(unused_variables, unused_mut, clippy::all)]
impl ::zeitner::__private::ConstrainedSystem<3, 2> for SteamGenerator {
    const POSITION_CONSTRAINTS: usize = 2;
    const MASS_IS_CONSTANT: bool = true;
    const DYNAMICS_DEPEND_ON_VELOCITY: bool = true;
    const SUMMARY: ::zeitner::__private::SceneSummary = ::zeitner::__private::SceneSummary {
        coordinates: 3,
        position_constraints: 2,
        velocity_constraints: 0,
        mass: ::zeitner::__private::MassKind::ConstantDiagonal,
        time_dependent: true,
        functions: &[
            ::zeitner::__private::FunctionSummary {
                name: "mass_matrix",
                blocks: &[
                    ::zeitner::__private::BlockSummary {
                        name: "m",
                        rows: 3,
                        cols: 1,
                        nonzeros: &[(0, 0), (1, 0), (2, 0)],
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
                        rows: 3,
                        cols: 1,
                        nonzeros: &[(0, 0), (1, 0), (2, 0)],
                    },
                ],
                ops: ::zeitner::__private::OpCounts {
                    adds: 2u64,
                    muls: 3u64,
                    divs: 0u64,
                    transcendental: 0u64,
                    opaque_calls: 1u64,
                },
                ops_unshared: ::zeitner::__private::OpCounts {
                    adds: 2u64,
                    muls: 3u64,
                    divs: 0u64,
                    transcendental: 0u64,
                    opaque_calls: 2u64,
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
                    adds: 4u64,
                    muls: 4u64,
                    divs: 0u64,
                    transcendental: 0u64,
                    opaque_calls: 0u64,
                },
                ops_unshared: ::zeitner::__private::OpCounts {
                    adds: 4u64,
                    muls: 4u64,
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
                        rows: 2,
                        cols: 3,
                        nonzeros: &[(0, 0), (0, 2), (1, 0), (1, 1)],
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
                    adds: 3u64,
                    muls: 5u64,
                    divs: 0u64,
                    transcendental: 0u64,
                    opaque_calls: 0u64,
                },
                ops_unshared: ::zeitner::__private::OpCounts {
                    adds: 3u64,
                    muls: 5u64,
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
                        rows: 2,
                        cols: 1,
                        nonzeros: &[(1, 0)],
                    },
                ],
                ops: ::zeitner::__private::OpCounts {
                    adds: 1u64,
                    muls: 4u64,
                    divs: 0u64,
                    transcendental: 0u64,
                    opaque_calls: 0u64,
                },
                ops_unshared: ::zeitner::__private::OpCounts {
                    adds: 1u64,
                    muls: 4u64,
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
                        rows: 3,
                        cols: 1,
                        nonzeros: &[(0, 0), (1, 0), (2, 0)],
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
                        nonzeros: &[(0, 0), (0, 2), (1, 0), (1, 1)],
                    },
                    ::zeitner::__private::BlockSummary {
                        name: "b",
                        rows: 2,
                        cols: 1,
                        nonzeros: &[(1, 0)],
                    },
                ],
                ops: ::zeitner::__private::OpCounts {
                    adds: 5u64,
                    muls: 9u64,
                    divs: 0u64,
                    transcendental: 0u64,
                    opaque_calls: 1u64,
                },
                ops_unshared: ::zeitner::__private::OpCounts {
                    adds: 5u64,
                    muls: 9u64,
                    divs: 0u64,
                    transcendental: 0u64,
                    opaque_calls: 2u64,
                },
            },
            ::zeitner::__private::FunctionSummary {
                name: "force_jacobians",
                blocks: &[
                    ::zeitner::__private::BlockSummary {
                        name: "dq",
                        rows: 3,
                        cols: 3,
                        nonzeros: &[],
                    },
                    ::zeitner::__private::BlockSummary {
                        name: "dv",
                        rows: 3,
                        cols: 3,
                        nonzeros: &[(0, 0)],
                    },
                ],
                ops: ::zeitner::__private::OpCounts {
                    adds: 1u64,
                    muls: 0u64,
                    divs: 0u64,
                    transcendental: 0u64,
                    opaque_calls: 0u64,
                },
                ops_unshared: ::zeitner::__private::OpCounts {
                    adds: 1u64,
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
                name: "rate_jacobians",
                blocks: &[
                    ::zeitner::__private::BlockSummary {
                        name: "wq",
                        rows: 2,
                        cols: 3,
                        nonzeros: &[(1, 0), (1, 1)],
                    },
                    ::zeitner::__private::BlockSummary {
                        name: "wv",
                        rows: 2,
                        cols: 3,
                        nonzeros: &[(0, 0), (0, 2), (1, 0), (1, 1)],
                    },
                ],
                ops: ::zeitner::__private::OpCounts {
                    adds: 2u64,
                    muls: 4u64,
                    divs: 0u64,
                    transcendental: 0u64,
                    opaque_calls: 0u64,
                },
                ops_unshared: ::zeitner::__private::OpCounts {
                    adds: 2u64,
                    muls: 4u64,
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
                        rows: 2,
                        cols: 3,
                        nonzeros: &[(1, 0), (1, 1)],
                    },
                    ::zeitner::__private::BlockSummary {
                        name: "cv",
                        rows: 2,
                        cols: 3,
                        nonzeros: &[(1, 0), (1, 1)],
                    },
                    ::zeitner::__private::BlockSummary {
                        name: "cp",
                        rows: 2,
                        cols: 4,
                        nonzeros: &[(0, 0), (1, 1)],
                    },
                ],
                ops: ::zeitner::__private::OpCounts {
                    adds: 1u64,
                    muls: 7u64,
                    divs: 0u64,
                    transcendental: 0u64,
                    opaque_calls: 0u64,
                },
                ops_unshared: ::zeitner::__private::OpCounts {
                    adds: 1u64,
                    muls: 7u64,
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
                        rows: 3,
                        cols: 4,
                        nonzeros: &[(0, 2), (0, 3), (1, 1), (1, 3), (2, 0)],
                    },
                ],
                ops: ::zeitner::__private::OpCounts {
                    adds: 5u64,
                    muls: 1u64,
                    divs: 0u64,
                    transcendental: 0u64,
                    opaque_calls: 0u64,
                },
                ops_unshared: ::zeitner::__private::OpCounts {
                    adds: 5u64,
                    muls: 1u64,
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
                        rows: 2,
                        cols: 4,
                        nonzeros: &[(0, 0), (1, 1)],
                    },
                    ::zeitner::__private::BlockSummary {
                        name: "dw",
                        rows: 2,
                        cols: 4,
                        nonzeros: &[(0, 0), (1, 1)],
                    },
                ],
                ops: ::zeitner::__private::OpCounts {
                    adds: 5u64,
                    muls: 3u64,
                    divs: 0u64,
                    transcendental: 0u64,
                    opaque_calls: 0u64,
                },
                ops_unshared: ::zeitner::__private::OpCounts {
                    adds: 5u64,
                    muls: 3u64,
                    divs: 0u64,
                    transcendental: 0u64,
                    opaque_calls: 0u64,
                },
            },
            ::zeitner::__private::FunctionSummary {
                name: "time_event_after",
                blocks: &[
                    ::zeitner::__private::BlockSummary {
                        name: "times",
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
        ],
    };
    type Mass = ::zeitner::__private::DiagonalMass<3>;
    type Storage = ::zeitner::__private::Dense;
    const SPARSITY: ::core::option::Option<::zeitner::__private::Sparsity> = ::core::option::Option::Some(::zeitner::__private::Sparsity {
        constraint_jacobian: &[(0, 0), (0, 2), (1, 0), (1, 1)],
        force_jacobians: [&[], &[(0, 0)]],
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
        let mut m = ::zeitner::__private::Vector::<3>::zeros();
        m[0] = self.m;
        m[1] = self.m;
        m[2] = self.j;
        ::zeitner::__private::DiagonalMass(m)
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
        let s0 = self.load(t);
        let mut f = ::zeitner::__private::Vector::<3>::zeros();
        f[0] = s0 - v[0] * self.d;
        f[1] = -(self.m * self.g);
        f[2] = s0 * self.h1;
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
        g[0] = q[0] - q[2] * self.h3;
        g[1] = q[0].powi(2) + (q[1] - self.h2).powi(2) - self.h2.powi(2);
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
        g[(0, 0)] = 1.0;
        g[(0, 2)] = -self.h3;
        g[(1, 0)] = 2.0 * q[0];
        g[(1, 1)] = 2.0 * (q[1] - self.h2);
        g
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
        w[0] = v[0] - v[2] * self.h3;
        w[1] = v[0] * (2.0 * q[0]) + v[1] * (2.0 * (q[1] - self.h2));
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
        b[1] = v[0] * (2.0 * v[0]) + v[1] * (2.0 * v[1]);
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
        let s0 = self.load(t);
        let mut m = ::zeitner::__private::Vector::<3>::zeros();
        let mut f = ::zeitner::__private::Vector::<3>::zeros();
        let mut g = ::zeitner::__private::Matrix::<2, 3>::zeros();
        let mut b = ::zeitner::__private::Vector::<2>::zeros();
        m[0] = self.m;
        m[1] = self.m;
        m[2] = self.j;
        f[0] = s0 - v[0] * self.d;
        f[1] = -(self.m * self.g);
        f[2] = s0 * self.h1;
        g[(0, 0)] = 1.0;
        g[(0, 2)] = -self.h3;
        g[(1, 0)] = 2.0 * q[0];
        g[(1, 1)] = 2.0 * (q[1] - self.h2);
        b[1] = v[0] * (2.0 * v[0]) + v[1] * (2.0 * v[1]);
        (::zeitner::__private::DiagonalMass(m), f, g, b)
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
        let mut dq = ::zeitner::__private::Matrix::<3, 3>::zeros();
        let mut dv = ::zeitner::__private::Matrix::<3, 3>::zeros();
        dv[(0, 0)] = -self.d;
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
        let s0 = 2.0 * lambda[1];
        let mut dq = ::zeitner::__private::Matrix::<3, 3>::zeros();
        let mut dv = ::zeitner::__private::Matrix::<3, 3>::zeros();
        dq[(0, 0)] = s0;
        dq[(1, 1)] = s0;
        (dq, dv)
    }
    #[inline]
    fn time_event_after(
        &self,
        after: ::zeitner::__private::Float,
    ) -> Option<::zeitner::__private::Float> {
        let times = {
            #[allow(unused_imports)]
            use ::zeitner::__private::Real as _;
            let mut times = ::zeitner::__private::Vector::<2>::zeros();
            times[0] = self.rise;
            times[1] = self.off;
            times
        };
        times
            .iter()
            .copied()
            .filter(|&s| s > after)
            .fold(
                None,
                |next: Option<::zeitner::__private::Float>, s| {
                    Some(next.map_or(s, |n| n.min(s)))
                },
            )
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
        values[0] = 1.0;
        values[1] = -self.h3;
        values[2] = 2.0 * q[0];
        values[3] = 2.0 * (q[1] - self.h2);
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
        values[0] = -self.d;
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
        let s0 = 2.0 * lambda[1];
        values[0] = s0;
        values[1] = s0;
    }
}
#[allow(unused_variables, unused_mut, clippy::all)]
impl ::zeitner::__private::ParametrisedSystem<3, 2, 4> for SteamGenerator {
    const PARAMETER_NAMES: [&'static str; 4] = ["h3", "h2", "d", "m"];
    #[inline]
    fn parameter_values(&self) -> ::zeitner::__private::Vector<4> {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let mut theta = ::zeitner::__private::Vector::<4>::zeros();
        theta[0] = self.h3;
        theta[1] = self.h2;
        theta[2] = self.d;
        theta[3] = self.m;
        theta
    }
    #[inline]
    fn parameter_force(
        &self,
        q: &::zeitner::__private::Vector<3>,
        v: &::zeitner::__private::Vector<3>,
        t: ::zeitner::__private::Float,
        lambda: &::zeitner::__private::Vector<2>,
        a: &::zeitner::__private::Vector<3>,
    ) -> ::zeitner::__private::Matrix<3, 4> {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let mut df = ::zeitner::__private::Matrix::<3, 4>::zeros();
        df[(0, 2)] = -v[0];
        df[(0, 3)] = -a[0];
        df[(1, 1)] = -(-2.0 * lambda[1]);
        df[(1, 3)] = -self.g - a[1];
        df[(2, 0)] = lambda[0];
        df
    }
    #[inline]
    fn parameter_constraints(
        &self,
        q: &::zeitner::__private::Vector<3>,
        v: &::zeitner::__private::Vector<3>,
        t: ::zeitner::__private::Float,
    ) -> (::zeitner::__private::Matrix<2, 4>, ::zeitner::__private::Matrix<2, 4>) {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let mut dg = ::zeitner::__private::Matrix::<2, 4>::zeros();
        let mut dw = ::zeitner::__private::Matrix::<2, 4>::zeros();
        dg[(0, 0)] = -q[2];
        dg[(1, 1)] = -(2.0 * (q[1] - self.h2)) - 2.0 * self.h2;
        dw[(0, 0)] = -v[2];
        dw[(1, 1)] = -2.0 * v[1];
        (dg, dw)
    }
    #[inline]
    fn rate_jacobians(
        &self,
        q: &::zeitner::__private::Vector<3>,
        v: &::zeitner::__private::Vector<3>,
        t: ::zeitner::__private::Float,
    ) -> (::zeitner::__private::Matrix<2, 3>, ::zeitner::__private::Matrix<2, 3>) {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let mut wq = ::zeitner::__private::Matrix::<2, 3>::zeros();
        let mut wv = ::zeitner::__private::Matrix::<2, 3>::zeros();
        wq[(1, 0)] = 2.0 * v[0];
        wq[(1, 1)] = 2.0 * v[1];
        wv[(0, 0)] = 1.0;
        wv[(0, 2)] = -self.h3;
        wv[(1, 0)] = 2.0 * q[0];
        wv[(1, 1)] = 2.0 * (q[1] - self.h2);
        (wq, wv)
    }
    #[inline]
    fn acceleration_constraint_jacobians(
        &self,
        q: &::zeitner::__private::Vector<3>,
        v: &::zeitner::__private::Vector<3>,
        t: ::zeitner::__private::Float,
        a: &::zeitner::__private::Vector<3>,
    ) -> (
        ::zeitner::__private::Matrix<2, 3>,
        ::zeitner::__private::Matrix<2, 3>,
        ::zeitner::__private::Matrix<2, 4>,
    ) {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let mut cq = ::zeitner::__private::Matrix::<2, 3>::zeros();
        let mut cv = ::zeitner::__private::Matrix::<2, 3>::zeros();
        let mut cp = ::zeitner::__private::Matrix::<2, 4>::zeros();
        cq[(1, 0)] = 2.0 * a[0];
        cq[(1, 1)] = 2.0 * a[1];
        cv[(1, 0)] = 2.0 * (2.0 * v[0]);
        cv[(1, 1)] = 2.0 * (2.0 * v[1]);
        cp[(0, 0)] = -a[2];
        cp[(1, 1)] = -2.0 * a[1];
        (cq, cv, cp)
    }
}
#[allow(dead_code)]
impl SteamGeneratorWithGap {
    fn mass(&self) -> [Float; 3] {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        [self.base.m, self.base.m, self.base.j]
    }
    fn force(
        &self,
        [_q1,
        _q2,
        _q3,
        ]: [Float; 3],
        [v1,
        _v2,
        _v3,
        ]: [Float; 3],
        t: Float,
    ) -> [Float; 3] {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let p = self.load(t);
        [p - self.base.d * v1, -self.base.m * self.base.g, p * self.base.h1]
    }
    fn constraints(&self, [q1, q2, _q3]: [Float; 3]) -> [Float; 1] {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        [q1 * q1 + (q2 - self.base.h2).powi(2) - self.base.h2 * self.base.h2]
    }
    /// The strut's travel left before it engages, pushed (first) and pulled (second).
    fn gaps(&self, [q1, _q2, q3]: [Float; 3]) -> [Float; 2] {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let travel = q1 - self.base.h3 * q3;
        [self.clearance - travel, self.clearance + travel]
    }
    fn restitution(&self) -> [Float; 2] {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        [self.e, self.e]
    }
    fn time_events(&self) -> [Float; 2] {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        [self.base.rise, self.base.off]
    }
    fn parameters(&self) -> [Float; 3] {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        [self.base.h3, self.clearance, self.base.d]
    }
}
#[allow(unused_variables, unused_mut, clippy::all)]
impl ::zeitner::__private::ConstrainedSystem<3, 3> for SteamGeneratorWithGap {
    const POSITION_CONSTRAINTS: usize = 3;
    const MASS_IS_CONSTANT: bool = true;
    const DYNAMICS_DEPEND_ON_VELOCITY: bool = true;
    const SUMMARY: ::zeitner::__private::SceneSummary = ::zeitner::__private::SceneSummary {
        coordinates: 3,
        position_constraints: 3,
        velocity_constraints: 0,
        mass: ::zeitner::__private::MassKind::ConstantDiagonal,
        time_dependent: true,
        functions: &[
            ::zeitner::__private::FunctionSummary {
                name: "mass_matrix",
                blocks: &[
                    ::zeitner::__private::BlockSummary {
                        name: "m",
                        rows: 3,
                        cols: 1,
                        nonzeros: &[(0, 0), (1, 0), (2, 0)],
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
                        rows: 3,
                        cols: 1,
                        nonzeros: &[(0, 0), (1, 0), (2, 0)],
                    },
                ],
                ops: ::zeitner::__private::OpCounts {
                    adds: 2u64,
                    muls: 3u64,
                    divs: 0u64,
                    transcendental: 0u64,
                    opaque_calls: 1u64,
                },
                ops_unshared: ::zeitner::__private::OpCounts {
                    adds: 2u64,
                    muls: 3u64,
                    divs: 0u64,
                    transcendental: 0u64,
                    opaque_calls: 2u64,
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
                    muls: 4u64,
                    divs: 0u64,
                    transcendental: 0u64,
                    opaque_calls: 0u64,
                },
                ops_unshared: ::zeitner::__private::OpCounts {
                    adds: 7u64,
                    muls: 5u64,
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
                        cols: 3,
                        nonzeros: &[(0, 0), (0, 1), (1, 0), (1, 2), (2, 0), (2, 2)],
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
                    adds: 4u64,
                    muls: 5u64,
                    divs: 0u64,
                    transcendental: 0u64,
                    opaque_calls: 0u64,
                },
                ops_unshared: ::zeitner::__private::OpCounts {
                    adds: 4u64,
                    muls: 6u64,
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
                        nonzeros: &[(0, 0)],
                    },
                ],
                ops: ::zeitner::__private::OpCounts {
                    adds: 1u64,
                    muls: 4u64,
                    divs: 0u64,
                    transcendental: 0u64,
                    opaque_calls: 0u64,
                },
                ops_unshared: ::zeitner::__private::OpCounts {
                    adds: 1u64,
                    muls: 4u64,
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
                        rows: 3,
                        cols: 1,
                        nonzeros: &[(0, 0), (1, 0), (2, 0)],
                    },
                    ::zeitner::__private::BlockSummary {
                        name: "f",
                        rows: 3,
                        cols: 1,
                        nonzeros: &[(0, 0), (1, 0), (2, 0)],
                    },
                    ::zeitner::__private::BlockSummary {
                        name: "g",
                        rows: 3,
                        cols: 3,
                        nonzeros: &[(0, 0), (0, 1), (1, 0), (1, 2), (2, 0), (2, 2)],
                    },
                    ::zeitner::__private::BlockSummary {
                        name: "b",
                        rows: 3,
                        cols: 1,
                        nonzeros: &[(0, 0)],
                    },
                ],
                ops: ::zeitner::__private::OpCounts {
                    adds: 5u64,
                    muls: 9u64,
                    divs: 0u64,
                    transcendental: 0u64,
                    opaque_calls: 1u64,
                },
                ops_unshared: ::zeitner::__private::OpCounts {
                    adds: 5u64,
                    muls: 9u64,
                    divs: 0u64,
                    transcendental: 0u64,
                    opaque_calls: 2u64,
                },
            },
            ::zeitner::__private::FunctionSummary {
                name: "force_jacobians",
                blocks: &[
                    ::zeitner::__private::BlockSummary {
                        name: "dq",
                        rows: 3,
                        cols: 3,
                        nonzeros: &[],
                    },
                    ::zeitner::__private::BlockSummary {
                        name: "dv",
                        rows: 3,
                        cols: 3,
                        nonzeros: &[(0, 0)],
                    },
                ],
                ops: ::zeitner::__private::OpCounts {
                    adds: 1u64,
                    muls: 0u64,
                    divs: 0u64,
                    transcendental: 0u64,
                    opaque_calls: 0u64,
                },
                ops_unshared: ::zeitner::__private::OpCounts {
                    adds: 1u64,
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
                name: "rate_jacobians",
                blocks: &[
                    ::zeitner::__private::BlockSummary {
                        name: "wq",
                        rows: 3,
                        cols: 3,
                        nonzeros: &[(0, 0), (0, 1)],
                    },
                    ::zeitner::__private::BlockSummary {
                        name: "wv",
                        rows: 3,
                        cols: 3,
                        nonzeros: &[(0, 0), (0, 1), (1, 0), (1, 2), (2, 0), (2, 2)],
                    },
                ],
                ops: ::zeitner::__private::OpCounts {
                    adds: 2u64,
                    muls: 4u64,
                    divs: 0u64,
                    transcendental: 0u64,
                    opaque_calls: 0u64,
                },
                ops_unshared: ::zeitner::__private::OpCounts {
                    adds: 2u64,
                    muls: 4u64,
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
                        rows: 3,
                        cols: 3,
                        nonzeros: &[(0, 0), (0, 1)],
                    },
                    ::zeitner::__private::BlockSummary {
                        name: "cv",
                        rows: 3,
                        cols: 3,
                        nonzeros: &[(0, 0), (0, 1)],
                    },
                    ::zeitner::__private::BlockSummary {
                        name: "cp",
                        rows: 3,
                        cols: 3,
                        nonzeros: &[(1, 0), (2, 0)],
                    },
                ],
                ops: ::zeitner::__private::OpCounts {
                    adds: 1u64,
                    muls: 6u64,
                    divs: 0u64,
                    transcendental: 0u64,
                    opaque_calls: 0u64,
                },
                ops_unshared: ::zeitner::__private::OpCounts {
                    adds: 1u64,
                    muls: 6u64,
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
                        rows: 3,
                        cols: 1,
                        nonzeros: &[(0, 0), (1, 0), (2, 0)],
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
                        rows: 3,
                        cols: 3,
                        nonzeros: &[(0, 2), (2, 0)],
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
                    adds: 2u64,
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
                        rows: 3,
                        cols: 3,
                        nonzeros: &[(1, 0), (1, 1), (2, 0), (2, 1)],
                    },
                    ::zeitner::__private::BlockSummary {
                        name: "dw",
                        rows: 3,
                        cols: 3,
                        nonzeros: &[(1, 0), (2, 0)],
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
                    adds: 2u64,
                    muls: 0u64,
                    divs: 0u64,
                    transcendental: 0u64,
                    opaque_calls: 0u64,
                },
            },
            ::zeitner::__private::FunctionSummary {
                name: "restitution",
                blocks: &[
                    ::zeitner::__private::BlockSummary {
                        name: "e",
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
                name: "time_event_after",
                blocks: &[
                    ::zeitner::__private::BlockSummary {
                        name: "times",
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
        ],
    };
    type Mass = ::zeitner::__private::DiagonalMass<3>;
    type Storage = ::zeitner::__private::Dense;
    const UNILATERAL_CONSTRAINTS: usize = 2usize;
    const SPARSITY: ::core::option::Option<::zeitner::__private::Sparsity> = ::core::option::Option::Some(::zeitner::__private::Sparsity {
        constraint_jacobian: &[(0, 0), (0, 1), (1, 0), (1, 2), (2, 0), (2, 2)],
        force_jacobians: [&[], &[(0, 0)]],
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
        let mut m = ::zeitner::__private::Vector::<3>::zeros();
        m[0] = self.base.m;
        m[1] = self.base.m;
        m[2] = self.base.j;
        ::zeitner::__private::DiagonalMass(m)
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
        let s0 = self.load(t);
        let mut f = ::zeitner::__private::Vector::<3>::zeros();
        f[0] = s0 - v[0] * self.base.d;
        f[1] = -(self.base.m * self.base.g);
        f[2] = s0 * self.base.h1;
        f
    }
    #[inline]
    fn constraint_residual(
        &self,
        q: &::zeitner::__private::Vector<3>,
        v: &::zeitner::__private::Vector<3>,
        t: ::zeitner::__private::Float,
    ) -> ::zeitner::__private::Vector<3> {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let s0 = q[0] - q[2] * self.base.h3;
        let mut g = ::zeitner::__private::Vector::<3>::zeros();
        g[0] = q[0].powi(2) + (q[1] - self.base.h2).powi(2) - self.base.h2.powi(2);
        g[1] = self.clearance - s0;
        g[2] = s0 + self.clearance;
        g
    }
    #[inline]
    fn constraint_jacobian(
        &self,
        q: &::zeitner::__private::Vector<3>,
        v: &::zeitner::__private::Vector<3>,
        t: ::zeitner::__private::Float,
    ) -> ::zeitner::__private::Matrix<3, 3> {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let mut g = ::zeitner::__private::Matrix::<3, 3>::zeros();
        g[(0, 0)] = 2.0 * q[0];
        g[(0, 1)] = 2.0 * (q[1] - self.base.h2);
        g[(1, 0)] = -1.0;
        g[(1, 2)] = self.base.h3;
        g[(2, 0)] = 1.0;
        g[(2, 2)] = -self.base.h3;
        g
    }
    #[inline]
    fn constraint_rate(
        &self,
        q: &::zeitner::__private::Vector<3>,
        v: &::zeitner::__private::Vector<3>,
        t: ::zeitner::__private::Float,
    ) -> ::zeitner::__private::Vector<3> {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let s0 = v[2] * self.base.h3;
        let mut w = ::zeitner::__private::Vector::<3>::zeros();
        w[0] = v[0] * (2.0 * q[0]) + v[1] * (2.0 * (q[1] - self.base.h2));
        w[1] = s0 - v[0];
        w[2] = v[0] - s0;
        w
    }
    #[inline]
    fn constraint_acceleration_bias(
        &self,
        q: &::zeitner::__private::Vector<3>,
        v: &::zeitner::__private::Vector<3>,
        t: ::zeitner::__private::Float,
    ) -> ::zeitner::__private::Vector<3> {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let mut b = ::zeitner::__private::Vector::<3>::zeros();
        b[0] = v[0] * (2.0 * v[0]) + v[1] * (2.0 * v[1]);
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
        ::zeitner::__private::Matrix<3, 3>,
        ::zeitner::__private::Vector<3>,
    ) {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let s0 = self.load(t);
        let mut m = ::zeitner::__private::Vector::<3>::zeros();
        let mut f = ::zeitner::__private::Vector::<3>::zeros();
        let mut g = ::zeitner::__private::Matrix::<3, 3>::zeros();
        let mut b = ::zeitner::__private::Vector::<3>::zeros();
        m[0] = self.base.m;
        m[1] = self.base.m;
        m[2] = self.base.j;
        f[0] = s0 - v[0] * self.base.d;
        f[1] = -(self.base.m * self.base.g);
        f[2] = s0 * self.base.h1;
        g[(0, 0)] = 2.0 * q[0];
        g[(0, 1)] = 2.0 * (q[1] - self.base.h2);
        g[(1, 0)] = -1.0;
        g[(1, 2)] = self.base.h3;
        g[(2, 0)] = 1.0;
        g[(2, 2)] = -self.base.h3;
        b[0] = v[0] * (2.0 * v[0]) + v[1] * (2.0 * v[1]);
        (::zeitner::__private::DiagonalMass(m), f, g, b)
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
        let mut dq = ::zeitner::__private::Matrix::<3, 3>::zeros();
        let mut dv = ::zeitner::__private::Matrix::<3, 3>::zeros();
        dv[(0, 0)] = -self.base.d;
        (dq, dv)
    }
    #[inline]
    fn constraint_force_jacobians(
        &self,
        q: &::zeitner::__private::Vector<3>,
        v: &::zeitner::__private::Vector<3>,
        t: ::zeitner::__private::Float,
        lambda: &::zeitner::__private::Vector<3>,
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
    fn restitution(&self, gap: usize) -> ::zeitner::__private::Float {
        let e = {
            #[allow(unused_imports)]
            use ::zeitner::__private::Real as _;
            let mut e = ::zeitner::__private::Vector::<2>::zeros();
            e[0] = self.e;
            e[1] = self.e;
            e
        };
        if gap < 2 { e[gap] } else { 0.0 }
    }
    #[inline]
    fn time_event_after(
        &self,
        after: ::zeitner::__private::Float,
    ) -> Option<::zeitner::__private::Float> {
        let times = {
            #[allow(unused_imports)]
            use ::zeitner::__private::Real as _;
            let mut times = ::zeitner::__private::Vector::<2>::zeros();
            times[0] = self.base.rise;
            times[1] = self.base.off;
            times
        };
        times
            .iter()
            .copied()
            .filter(|&s| s > after)
            .fold(
                None,
                |next: Option<::zeitner::__private::Float>, s| {
                    Some(next.map_or(s, |n| n.min(s)))
                },
            )
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
        values[1] = 2.0 * (q[1] - self.base.h2);
        values[2] = -1.0;
        values[3] = self.base.h3;
        values[4] = 1.0;
        values[5] = -self.base.h3;
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
        values[0] = -self.base.d;
    }
    #[inline]
    fn constraint_force_jacobian_nonzeros(
        &self,
        q: &::zeitner::__private::Vector<3>,
        v: &::zeitner::__private::Vector<3>,
        t: ::zeitner::__private::Float,
        lambda: &::zeitner::__private::Vector<3>,
        values: &mut [::zeitner::__private::Float],
    ) {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let s0 = 2.0 * lambda[0];
        values[0] = s0;
        values[1] = s0;
    }
}
#[allow(unused_variables, unused_mut, clippy::all)]
impl ::zeitner::__private::ParametrisedSystem<3, 3, 3> for SteamGeneratorWithGap {
    const PARAMETER_NAMES: [&'static str; 3] = ["base.h3", "clearance", "base.d"];
    #[inline]
    fn parameter_values(&self) -> ::zeitner::__private::Vector<3> {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let mut theta = ::zeitner::__private::Vector::<3>::zeros();
        theta[0] = self.base.h3;
        theta[1] = self.clearance;
        theta[2] = self.base.d;
        theta
    }
    #[inline]
    fn parameter_force(
        &self,
        q: &::zeitner::__private::Vector<3>,
        v: &::zeitner::__private::Vector<3>,
        t: ::zeitner::__private::Float,
        lambda: &::zeitner::__private::Vector<3>,
        a: &::zeitner::__private::Vector<3>,
    ) -> ::zeitner::__private::Matrix<3, 3> {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let mut df = ::zeitner::__private::Matrix::<3, 3>::zeros();
        df[(0, 2)] = -v[0];
        df[(2, 0)] = lambda[2] - lambda[1];
        df
    }
    #[inline]
    fn parameter_constraints(
        &self,
        q: &::zeitner::__private::Vector<3>,
        v: &::zeitner::__private::Vector<3>,
        t: ::zeitner::__private::Float,
    ) -> (::zeitner::__private::Matrix<3, 3>, ::zeitner::__private::Matrix<3, 3>) {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let mut dg = ::zeitner::__private::Matrix::<3, 3>::zeros();
        let mut dw = ::zeitner::__private::Matrix::<3, 3>::zeros();
        dg[(1, 0)] = q[2];
        dg[(1, 1)] = 1.0;
        dg[(2, 0)] = -q[2];
        dg[(2, 1)] = 1.0;
        dw[(1, 0)] = v[2];
        dw[(2, 0)] = -v[2];
        (dg, dw)
    }
    #[inline]
    fn rate_jacobians(
        &self,
        q: &::zeitner::__private::Vector<3>,
        v: &::zeitner::__private::Vector<3>,
        t: ::zeitner::__private::Float,
    ) -> (::zeitner::__private::Matrix<3, 3>, ::zeitner::__private::Matrix<3, 3>) {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let mut wq = ::zeitner::__private::Matrix::<3, 3>::zeros();
        let mut wv = ::zeitner::__private::Matrix::<3, 3>::zeros();
        wq[(0, 0)] = 2.0 * v[0];
        wq[(0, 1)] = 2.0 * v[1];
        wv[(0, 0)] = 2.0 * q[0];
        wv[(0, 1)] = 2.0 * (q[1] - self.base.h2);
        wv[(1, 0)] = -1.0;
        wv[(1, 2)] = self.base.h3;
        wv[(2, 0)] = 1.0;
        wv[(2, 2)] = -self.base.h3;
        (wq, wv)
    }
    #[inline]
    fn acceleration_constraint_jacobians(
        &self,
        q: &::zeitner::__private::Vector<3>,
        v: &::zeitner::__private::Vector<3>,
        t: ::zeitner::__private::Float,
        a: &::zeitner::__private::Vector<3>,
    ) -> (
        ::zeitner::__private::Matrix<3, 3>,
        ::zeitner::__private::Matrix<3, 3>,
        ::zeitner::__private::Matrix<3, 3>,
    ) {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let mut cq = ::zeitner::__private::Matrix::<3, 3>::zeros();
        let mut cv = ::zeitner::__private::Matrix::<3, 3>::zeros();
        let mut cp = ::zeitner::__private::Matrix::<3, 3>::zeros();
        cq[(0, 0)] = 2.0 * a[0];
        cq[(0, 1)] = 2.0 * a[1];
        cv[(0, 0)] = 2.0 * (2.0 * v[0]);
        cv[(0, 1)] = 2.0 * (2.0 * v[1]);
        cp[(1, 0)] = a[2];
        cp[(2, 0)] = -a[2];
        (cq, cv, cp)
    }
}
#[allow(dead_code)]
impl SlidingSupportSteamGenerator {
    fn mass(&self) -> [Float; 3] {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        [self.base.m, self.base.m, self.base.j]
    }
    fn force(
        &self,
        [_q1,
        _q2,
        _q3,
        ]: [Float; 3],
        [v1,
        _v2,
        _v3,
        ]: [Float; 3],
        t: Float,
    ) -> [Float; 3] {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let p = self.load(t);
        [p - self.base.d * v1, -self.base.m * self.base.g, p * self.base.h1]
    }
    fn constraints(&self, [q1, q2, _q3]: [Float; 3]) -> [Float; 1] {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        [q1 * q1 + (q2 - self.base.h2).powi(2) - self.base.h2 * self.base.h2]
    }
    /// C's travel left before it meets the guide's plate, pushed (first) and pulled (second).
    fn gaps(&self, [q1, _q2, q3]: [Float; 3]) -> [Float; 2] {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let travel = q1 - self.base.h3 * q3;
        [self.clearance - travel, self.clearance + travel]
    }
    /// C's velocity along the guide, on either plate.
    fn slips(&self, _q: [Float; 3], [_v1, v2, _v3]: [Float; 3]) -> [Float; 2] {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        [v2, v2]
    }
    fn restitution(&self) -> [Float; 2] {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        [self.e, self.e]
    }
    fn friction(&self) -> [Float; 2] {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        [self.mu, self.mu]
    }
    fn time_events(&self) -> [Float; 2] {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        [self.base.rise, self.base.off]
    }
}
#[allow(unused_variables, unused_mut, clippy::all)]
impl ::zeitner::__private::ConstrainedSystem<3, 5> for SlidingSupportSteamGenerator {
    const POSITION_CONSTRAINTS: usize = 3;
    const MASS_IS_CONSTANT: bool = true;
    const DYNAMICS_DEPEND_ON_VELOCITY: bool = true;
    const SUMMARY: ::zeitner::__private::SceneSummary = ::zeitner::__private::SceneSummary {
        coordinates: 3,
        position_constraints: 3,
        velocity_constraints: 2,
        mass: ::zeitner::__private::MassKind::ConstantDiagonal,
        time_dependent: true,
        functions: &[
            ::zeitner::__private::FunctionSummary {
                name: "mass_matrix",
                blocks: &[
                    ::zeitner::__private::BlockSummary {
                        name: "m",
                        rows: 3,
                        cols: 1,
                        nonzeros: &[(0, 0), (1, 0), (2, 0)],
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
                        rows: 3,
                        cols: 1,
                        nonzeros: &[(0, 0), (1, 0), (2, 0)],
                    },
                ],
                ops: ::zeitner::__private::OpCounts {
                    adds: 2u64,
                    muls: 3u64,
                    divs: 0u64,
                    transcendental: 0u64,
                    opaque_calls: 1u64,
                },
                ops_unshared: ::zeitner::__private::OpCounts {
                    adds: 2u64,
                    muls: 3u64,
                    divs: 0u64,
                    transcendental: 0u64,
                    opaque_calls: 2u64,
                },
            },
            ::zeitner::__private::FunctionSummary {
                name: "constraint_residual",
                blocks: &[
                    ::zeitner::__private::BlockSummary {
                        name: "g",
                        rows: 5,
                        cols: 1,
                        nonzeros: &[(0, 0), (1, 0), (2, 0), (3, 0), (4, 0)],
                    },
                ],
                ops: ::zeitner::__private::OpCounts {
                    adds: 6u64,
                    muls: 4u64,
                    divs: 0u64,
                    transcendental: 0u64,
                    opaque_calls: 0u64,
                },
                ops_unshared: ::zeitner::__private::OpCounts {
                    adds: 7u64,
                    muls: 5u64,
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
                        rows: 5,
                        cols: 3,
                        nonzeros: &[
                            (0, 0),
                            (0, 1),
                            (1, 0),
                            (1, 2),
                            (2, 0),
                            (2, 2),
                            (3, 1),
                            (4, 1),
                        ],
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
                name: "constraint_position_partials",
                blocks: &[
                    ::zeitner::__private::BlockSummary {
                        name: "p",
                        rows: 5,
                        cols: 3,
                        nonzeros: &[(0, 0), (0, 1), (1, 0), (1, 2), (2, 0), (2, 2)],
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
                name: "constraint_rate",
                blocks: &[
                    ::zeitner::__private::BlockSummary {
                        name: "w",
                        rows: 5,
                        cols: 1,
                        nonzeros: &[(0, 0), (1, 0), (2, 0), (3, 0), (4, 0)],
                    },
                ],
                ops: ::zeitner::__private::OpCounts {
                    adds: 4u64,
                    muls: 5u64,
                    divs: 0u64,
                    transcendental: 0u64,
                    opaque_calls: 0u64,
                },
                ops_unshared: ::zeitner::__private::OpCounts {
                    adds: 4u64,
                    muls: 6u64,
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
                        rows: 5,
                        cols: 1,
                        nonzeros: &[(0, 0)],
                    },
                ],
                ops: ::zeitner::__private::OpCounts {
                    adds: 1u64,
                    muls: 4u64,
                    divs: 0u64,
                    transcendental: 0u64,
                    opaque_calls: 0u64,
                },
                ops_unshared: ::zeitner::__private::OpCounts {
                    adds: 1u64,
                    muls: 4u64,
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
                        rows: 3,
                        cols: 1,
                        nonzeros: &[(0, 0), (1, 0), (2, 0)],
                    },
                    ::zeitner::__private::BlockSummary {
                        name: "f",
                        rows: 3,
                        cols: 1,
                        nonzeros: &[(0, 0), (1, 0), (2, 0)],
                    },
                    ::zeitner::__private::BlockSummary {
                        name: "g",
                        rows: 5,
                        cols: 3,
                        nonzeros: &[
                            (0, 0),
                            (0, 1),
                            (1, 0),
                            (1, 2),
                            (2, 0),
                            (2, 2),
                            (3, 1),
                            (4, 1),
                        ],
                    },
                    ::zeitner::__private::BlockSummary {
                        name: "b",
                        rows: 5,
                        cols: 1,
                        nonzeros: &[(0, 0)],
                    },
                ],
                ops: ::zeitner::__private::OpCounts {
                    adds: 5u64,
                    muls: 9u64,
                    divs: 0u64,
                    transcendental: 0u64,
                    opaque_calls: 1u64,
                },
                ops_unshared: ::zeitner::__private::OpCounts {
                    adds: 5u64,
                    muls: 9u64,
                    divs: 0u64,
                    transcendental: 0u64,
                    opaque_calls: 2u64,
                },
            },
            ::zeitner::__private::FunctionSummary {
                name: "force_jacobians",
                blocks: &[
                    ::zeitner::__private::BlockSummary {
                        name: "dq",
                        rows: 3,
                        cols: 3,
                        nonzeros: &[],
                    },
                    ::zeitner::__private::BlockSummary {
                        name: "dv",
                        rows: 3,
                        cols: 3,
                        nonzeros: &[(0, 0)],
                    },
                ],
                ops: ::zeitner::__private::OpCounts {
                    adds: 1u64,
                    muls: 0u64,
                    divs: 0u64,
                    transcendental: 0u64,
                    opaque_calls: 0u64,
                },
                ops_unshared: ::zeitner::__private::OpCounts {
                    adds: 1u64,
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
                name: "restitution",
                blocks: &[
                    ::zeitner::__private::BlockSummary {
                        name: "e",
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
                name: "friction",
                blocks: &[
                    ::zeitner::__private::BlockSummary {
                        name: "mu",
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
                name: "time_event_after",
                blocks: &[
                    ::zeitner::__private::BlockSummary {
                        name: "times",
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
        ],
    };
    type Mass = ::zeitner::__private::DiagonalMass<3>;
    type Storage = ::zeitner::__private::Dense;
    const UNILATERAL_CONSTRAINTS: usize = 2usize;
    const SLIDING_CONTACTS: usize = 2usize;
    const SPARSITY: ::core::option::Option<::zeitner::__private::Sparsity> = ::core::option::Option::Some(::zeitner::__private::Sparsity {
        constraint_jacobian: &[
            (0, 0),
            (0, 1),
            (1, 0),
            (1, 2),
            (2, 0),
            (2, 2),
            (3, 1),
            (4, 1),
        ],
        force_jacobians: [&[], &[(0, 0)]],
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
        let mut m = ::zeitner::__private::Vector::<3>::zeros();
        m[0] = self.base.m;
        m[1] = self.base.m;
        m[2] = self.base.j;
        ::zeitner::__private::DiagonalMass(m)
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
        let s0 = self.load(t);
        let mut f = ::zeitner::__private::Vector::<3>::zeros();
        f[0] = s0 - v[0] * self.base.d;
        f[1] = -(self.base.m * self.base.g);
        f[2] = s0 * self.base.h1;
        f
    }
    #[inline]
    fn constraint_residual(
        &self,
        q: &::zeitner::__private::Vector<3>,
        v: &::zeitner::__private::Vector<3>,
        t: ::zeitner::__private::Float,
    ) -> ::zeitner::__private::Vector<5> {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let s0 = q[0] - q[2] * self.base.h3;
        let mut g = ::zeitner::__private::Vector::<5>::zeros();
        g[0] = q[0].powi(2) + (q[1] - self.base.h2).powi(2) - self.base.h2.powi(2);
        g[1] = self.clearance - s0;
        g[2] = s0 + self.clearance;
        g[3] = v[1];
        g[4] = v[1];
        g
    }
    #[inline]
    fn constraint_jacobian(
        &self,
        q: &::zeitner::__private::Vector<3>,
        v: &::zeitner::__private::Vector<3>,
        t: ::zeitner::__private::Float,
    ) -> ::zeitner::__private::Matrix<5, 3> {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let mut g = ::zeitner::__private::Matrix::<5, 3>::zeros();
        g[(0, 0)] = 2.0 * q[0];
        g[(0, 1)] = 2.0 * (q[1] - self.base.h2);
        g[(1, 0)] = -1.0;
        g[(1, 2)] = self.base.h3;
        g[(2, 0)] = 1.0;
        g[(2, 2)] = -self.base.h3;
        g[(3, 1)] = 1.0;
        g[(4, 1)] = 1.0;
        g
    }
    #[inline]
    fn constraint_position_partials(
        &self,
        q: &::zeitner::__private::Vector<3>,
        v: &::zeitner::__private::Vector<3>,
        t: ::zeitner::__private::Float,
    ) -> ::zeitner::__private::Matrix<5, 3> {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let mut p = ::zeitner::__private::Matrix::<5, 3>::zeros();
        p[(0, 0)] = 2.0 * q[0];
        p[(0, 1)] = 2.0 * (q[1] - self.base.h2);
        p[(1, 0)] = -1.0;
        p[(1, 2)] = self.base.h3;
        p[(2, 0)] = 1.0;
        p[(2, 2)] = -self.base.h3;
        p
    }
    #[inline]
    fn constraint_rate(
        &self,
        q: &::zeitner::__private::Vector<3>,
        v: &::zeitner::__private::Vector<3>,
        t: ::zeitner::__private::Float,
    ) -> ::zeitner::__private::Vector<5> {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let s0 = v[2] * self.base.h3;
        let mut w = ::zeitner::__private::Vector::<5>::zeros();
        w[0] = v[0] * (2.0 * q[0]) + v[1] * (2.0 * (q[1] - self.base.h2));
        w[1] = s0 - v[0];
        w[2] = v[0] - s0;
        w[3] = v[1];
        w[4] = v[1];
        w
    }
    #[inline]
    fn constraint_acceleration_bias(
        &self,
        q: &::zeitner::__private::Vector<3>,
        v: &::zeitner::__private::Vector<3>,
        t: ::zeitner::__private::Float,
    ) -> ::zeitner::__private::Vector<5> {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let mut b = ::zeitner::__private::Vector::<5>::zeros();
        b[0] = v[0] * (2.0 * v[0]) + v[1] * (2.0 * v[1]);
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
        ::zeitner::__private::Matrix<5, 3>,
        ::zeitner::__private::Vector<5>,
    ) {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let s0 = self.load(t);
        let mut m = ::zeitner::__private::Vector::<3>::zeros();
        let mut f = ::zeitner::__private::Vector::<3>::zeros();
        let mut g = ::zeitner::__private::Matrix::<5, 3>::zeros();
        let mut b = ::zeitner::__private::Vector::<5>::zeros();
        m[0] = self.base.m;
        m[1] = self.base.m;
        m[2] = self.base.j;
        f[0] = s0 - v[0] * self.base.d;
        f[1] = -(self.base.m * self.base.g);
        f[2] = s0 * self.base.h1;
        g[(0, 0)] = 2.0 * q[0];
        g[(0, 1)] = 2.0 * (q[1] - self.base.h2);
        g[(1, 0)] = -1.0;
        g[(1, 2)] = self.base.h3;
        g[(2, 0)] = 1.0;
        g[(2, 2)] = -self.base.h3;
        g[(3, 1)] = 1.0;
        g[(4, 1)] = 1.0;
        b[0] = v[0] * (2.0 * v[0]) + v[1] * (2.0 * v[1]);
        (::zeitner::__private::DiagonalMass(m), f, g, b)
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
        let mut dq = ::zeitner::__private::Matrix::<3, 3>::zeros();
        let mut dv = ::zeitner::__private::Matrix::<3, 3>::zeros();
        dv[(0, 0)] = -self.base.d;
        (dq, dv)
    }
    #[inline]
    fn constraint_force_jacobians(
        &self,
        q: &::zeitner::__private::Vector<3>,
        v: &::zeitner::__private::Vector<3>,
        t: ::zeitner::__private::Float,
        lambda: &::zeitner::__private::Vector<5>,
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
    fn restitution(&self, gap: usize) -> ::zeitner::__private::Float {
        let e = {
            #[allow(unused_imports)]
            use ::zeitner::__private::Real as _;
            let mut e = ::zeitner::__private::Vector::<2>::zeros();
            e[0] = self.e;
            e[1] = self.e;
            e
        };
        if gap < 2 { e[gap] } else { 0.0 }
    }
    #[inline]
    fn friction(&self, gap: usize) -> ::zeitner::__private::Float {
        let mu = {
            #[allow(unused_imports)]
            use ::zeitner::__private::Real as _;
            let mut mu = ::zeitner::__private::Vector::<2>::zeros();
            mu[0] = self.mu;
            mu[1] = self.mu;
            mu
        };
        if gap < 2 { mu[gap] } else { 0.0 }
    }
    #[inline]
    fn time_event_after(
        &self,
        after: ::zeitner::__private::Float,
    ) -> Option<::zeitner::__private::Float> {
        let times = {
            #[allow(unused_imports)]
            use ::zeitner::__private::Real as _;
            let mut times = ::zeitner::__private::Vector::<2>::zeros();
            times[0] = self.base.rise;
            times[1] = self.base.off;
            times
        };
        times
            .iter()
            .copied()
            .filter(|&s| s > after)
            .fold(
                None,
                |next: Option<::zeitner::__private::Float>, s| {
                    Some(next.map_or(s, |n| n.min(s)))
                },
            )
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
        values[1] = 2.0 * (q[1] - self.base.h2);
        values[2] = -1.0;
        values[3] = self.base.h3;
        values[4] = 1.0;
        values[5] = -self.base.h3;
        values[6] = 1.0;
        values[7] = 1.0;
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
        values[0] = -self.base.d;
    }
    #[inline]
    fn constraint_force_jacobian_nonzeros(
        &self,
        q: &::zeitner::__private::Vector<3>,
        v: &::zeitner::__private::Vector<3>,
        t: ::zeitner::__private::Float,
        lambda: &::zeitner::__private::Vector<5>,
        values: &mut [::zeitner::__private::Float],
    ) {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let s0 = 2.0 * lambda[0];
        values[0] = s0;
        values[1] = s0;
    }
}
