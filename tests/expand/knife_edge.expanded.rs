#[allow(dead_code)]
impl KnifeEdge {
    fn mass(&self) -> [Float; 3] {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        [self.m, self.m, self.j]
    }
    fn force(&self) -> [Float; 3] {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        [self.m * self.g * self.alpha.sin(), 0.0, 0.0]
    }
    fn velocity_constraints(
        &self,
        [_x,
        _y,
        theta,
        ]: [Float; 3],
        [vx,
        vy,
        _w,
        ]: [Float; 3],
    ) -> [Float; 1] {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        [-theta.sin() * vx + theta.cos() * vy]
    }
    /// For sensitivities: the slope, gravity and the mass (on which the motion does not depend).
    fn parameters(&self) -> [Float; 3] {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        [self.alpha, self.g, self.m]
    }
}
#[allow(unused_variables, unused_mut, clippy::all)]
impl ::zeitner::__private::ConstrainedSystem<3, 1> for KnifeEdge {
    const POSITION_CONSTRAINTS: usize = 0;
    const MASS_IS_CONSTANT: bool = true;
    const DYNAMICS_DEPEND_ON_VELOCITY: bool = false;
    const SUMMARY: ::zeitner::__private::SceneSummary = ::zeitner::__private::SceneSummary {
        coordinates: 3,
        position_constraints: 0,
        velocity_constraints: 1,
        mass: ::zeitner::__private::MassKind::ConstantDiagonal,
        time_dependent: false,
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
                        nonzeros: &[(0, 0)],
                    },
                ],
                ops: ::zeitner::__private::OpCounts {
                    adds: 0u64,
                    muls: 2u64,
                    divs: 0u64,
                    transcendental: 1u64,
                    opaque_calls: 0u64,
                },
                ops_unshared: ::zeitner::__private::OpCounts {
                    adds: 0u64,
                    muls: 2u64,
                    divs: 0u64,
                    transcendental: 1u64,
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
                    adds: 1u64,
                    muls: 2u64,
                    divs: 0u64,
                    transcendental: 2u64,
                    opaque_calls: 0u64,
                },
                ops_unshared: ::zeitner::__private::OpCounts {
                    adds: 1u64,
                    muls: 2u64,
                    divs: 0u64,
                    transcendental: 2u64,
                    opaque_calls: 0u64,
                },
            },
            ::zeitner::__private::FunctionSummary {
                name: "constraint_jacobian",
                blocks: &[
                    ::zeitner::__private::BlockSummary {
                        name: "g",
                        rows: 1,
                        cols: 3,
                        nonzeros: &[(0, 0), (0, 1)],
                    },
                ],
                ops: ::zeitner::__private::OpCounts {
                    adds: 1u64,
                    muls: 0u64,
                    divs: 0u64,
                    transcendental: 2u64,
                    opaque_calls: 0u64,
                },
                ops_unshared: ::zeitner::__private::OpCounts {
                    adds: 1u64,
                    muls: 0u64,
                    divs: 0u64,
                    transcendental: 2u64,
                    opaque_calls: 0u64,
                },
            },
            ::zeitner::__private::FunctionSummary {
                name: "constraint_position_partials",
                blocks: &[
                    ::zeitner::__private::BlockSummary {
                        name: "p",
                        rows: 1,
                        cols: 3,
                        nonzeros: &[(0, 2)],
                    },
                ],
                ops: ::zeitner::__private::OpCounts {
                    adds: 2u64,
                    muls: 2u64,
                    divs: 0u64,
                    transcendental: 2u64,
                    opaque_calls: 0u64,
                },
                ops_unshared: ::zeitner::__private::OpCounts {
                    adds: 2u64,
                    muls: 2u64,
                    divs: 0u64,
                    transcendental: 2u64,
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
                    adds: 1u64,
                    muls: 2u64,
                    divs: 0u64,
                    transcendental: 2u64,
                    opaque_calls: 0u64,
                },
                ops_unshared: ::zeitner::__private::OpCounts {
                    adds: 1u64,
                    muls: 2u64,
                    divs: 0u64,
                    transcendental: 2u64,
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
                    adds: 2u64,
                    muls: 3u64,
                    divs: 0u64,
                    transcendental: 2u64,
                    opaque_calls: 0u64,
                },
                ops_unshared: ::zeitner::__private::OpCounts {
                    adds: 2u64,
                    muls: 3u64,
                    divs: 0u64,
                    transcendental: 2u64,
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
                        nonzeros: &[(0, 0)],
                    },
                    ::zeitner::__private::BlockSummary {
                        name: "g",
                        rows: 1,
                        cols: 3,
                        nonzeros: &[(0, 0), (0, 1)],
                    },
                    ::zeitner::__private::BlockSummary {
                        name: "b",
                        rows: 1,
                        cols: 1,
                        nonzeros: &[(0, 0)],
                    },
                ],
                ops: ::zeitner::__private::OpCounts {
                    adds: 3u64,
                    muls: 5u64,
                    divs: 0u64,
                    transcendental: 3u64,
                    opaque_calls: 0u64,
                },
                ops_unshared: ::zeitner::__private::OpCounts {
                    adds: 3u64,
                    muls: 5u64,
                    divs: 0u64,
                    transcendental: 5u64,
                    opaque_calls: 0u64,
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
                        rows: 3,
                        cols: 3,
                        nonzeros: &[(0, 2), (1, 2)],
                    },
                    ::zeitner::__private::BlockSummary {
                        name: "dv",
                        rows: 3,
                        cols: 3,
                        nonzeros: &[],
                    },
                ],
                ops: ::zeitner::__private::OpCounts {
                    adds: 2u64,
                    muls: 2u64,
                    divs: 0u64,
                    transcendental: 2u64,
                    opaque_calls: 0u64,
                },
                ops_unshared: ::zeitner::__private::OpCounts {
                    adds: 2u64,
                    muls: 2u64,
                    divs: 0u64,
                    transcendental: 2u64,
                    opaque_calls: 0u64,
                },
            },
            ::zeitner::__private::FunctionSummary {
                name: "rate_jacobians",
                blocks: &[
                    ::zeitner::__private::BlockSummary {
                        name: "wq",
                        rows: 1,
                        cols: 3,
                        nonzeros: &[(0, 2)],
                    },
                    ::zeitner::__private::BlockSummary {
                        name: "wv",
                        rows: 1,
                        cols: 3,
                        nonzeros: &[(0, 0), (0, 1)],
                    },
                ],
                ops: ::zeitner::__private::OpCounts {
                    adds: 3u64,
                    muls: 2u64,
                    divs: 0u64,
                    transcendental: 2u64,
                    opaque_calls: 0u64,
                },
                ops_unshared: ::zeitner::__private::OpCounts {
                    adds: 3u64,
                    muls: 2u64,
                    divs: 0u64,
                    transcendental: 4u64,
                    opaque_calls: 0u64,
                },
            },
            ::zeitner::__private::FunctionSummary {
                name: "acceleration_constraint_jacobians",
                blocks: &[
                    ::zeitner::__private::BlockSummary {
                        name: "cq",
                        rows: 1,
                        cols: 3,
                        nonzeros: &[(0, 2)],
                    },
                    ::zeitner::__private::BlockSummary {
                        name: "cv",
                        rows: 1,
                        cols: 3,
                        nonzeros: &[(0, 0), (0, 1), (0, 2)],
                    },
                    ::zeitner::__private::BlockSummary {
                        name: "cp",
                        rows: 1,
                        cols: 3,
                        nonzeros: &[],
                    },
                ],
                ops: ::zeitner::__private::OpCounts {
                    adds: 7u64,
                    muls: 9u64,
                    divs: 0u64,
                    transcendental: 2u64,
                    opaque_calls: 0u64,
                },
                ops_unshared: ::zeitner::__private::OpCounts {
                    adds: 7u64,
                    muls: 9u64,
                    divs: 0u64,
                    transcendental: 8u64,
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
                        nonzeros: &[(0, 0), (0, 1), (0, 2), (1, 2)],
                    },
                ],
                ops: ::zeitner::__private::OpCounts {
                    adds: 2u64,
                    muls: 4u64,
                    divs: 0u64,
                    transcendental: 2u64,
                    opaque_calls: 0u64,
                },
                ops_unshared: ::zeitner::__private::OpCounts {
                    adds: 2u64,
                    muls: 4u64,
                    divs: 0u64,
                    transcendental: 3u64,
                    opaque_calls: 0u64,
                },
            },
            ::zeitner::__private::FunctionSummary {
                name: "parameter_constraints",
                blocks: &[
                    ::zeitner::__private::BlockSummary {
                        name: "dg",
                        rows: 1,
                        cols: 3,
                        nonzeros: &[],
                    },
                    ::zeitner::__private::BlockSummary {
                        name: "dw",
                        rows: 1,
                        cols: 3,
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
    type Mass = ::zeitner::__private::DiagonalMass<3>;
    type Storage = ::zeitner::__private::Dense;
    const SPARSITY: ::core::option::Option<::zeitner::__private::Sparsity> = ::core::option::Option::Some(::zeitner::__private::Sparsity {
        constraint_jacobian: &[(0, 0), (0, 1)],
        force_jacobians: [&[], &[]],
        constraint_force_jacobians: [&[(0, 2), (1, 2)], &[]],
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
        let mut f = ::zeitner::__private::Vector::<3>::zeros();
        f[0] = self.m * self.g * self.alpha.sin();
        f
    }
    #[inline]
    fn constraint_residual(
        &self,
        q: &::zeitner::__private::Vector<3>,
        v: &::zeitner::__private::Vector<3>,
        t: ::zeitner::__private::Float,
    ) -> ::zeitner::__private::Vector<1> {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let mut g = ::zeitner::__private::Vector::<1>::zeros();
        g[0] = v[1] * q[2].cos() - v[0] * q[2].sin();
        g
    }
    #[inline]
    fn constraint_jacobian(
        &self,
        q: &::zeitner::__private::Vector<3>,
        v: &::zeitner::__private::Vector<3>,
        t: ::zeitner::__private::Float,
    ) -> ::zeitner::__private::Matrix<1, 3> {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let mut g = ::zeitner::__private::Matrix::<1, 3>::zeros();
        g[(0, 0)] = -q[2].sin();
        g[(0, 1)] = q[2].cos();
        g
    }
    #[inline]
    fn constraint_position_partials(
        &self,
        q: &::zeitner::__private::Vector<3>,
        v: &::zeitner::__private::Vector<3>,
        t: ::zeitner::__private::Float,
    ) -> ::zeitner::__private::Matrix<1, 3> {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let mut p = ::zeitner::__private::Matrix::<1, 3>::zeros();
        p[(0, 2)] = -(v[1] * q[2].sin()) - v[0] * q[2].cos();
        p
    }
    #[inline]
    fn constraint_rate(
        &self,
        q: &::zeitner::__private::Vector<3>,
        v: &::zeitner::__private::Vector<3>,
        t: ::zeitner::__private::Float,
    ) -> ::zeitner::__private::Vector<1> {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let mut w = ::zeitner::__private::Vector::<1>::zeros();
        w[0] = v[1] * q[2].cos() - v[0] * q[2].sin();
        w
    }
    #[inline]
    fn constraint_acceleration_bias(
        &self,
        q: &::zeitner::__private::Vector<3>,
        v: &::zeitner::__private::Vector<3>,
        t: ::zeitner::__private::Float,
    ) -> ::zeitner::__private::Vector<1> {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let mut b = ::zeitner::__private::Vector::<1>::zeros();
        b[0] = v[2] * (-(v[1] * q[2].sin()) - v[0] * q[2].cos());
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
        ::zeitner::__private::Matrix<1, 3>,
        ::zeitner::__private::Vector<1>,
    ) {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let s0 = q[2].sin();
        let s1 = q[2].cos();
        let mut m = ::zeitner::__private::Vector::<3>::zeros();
        let mut f = ::zeitner::__private::Vector::<3>::zeros();
        let mut g = ::zeitner::__private::Matrix::<1, 3>::zeros();
        let mut b = ::zeitner::__private::Vector::<1>::zeros();
        m[0] = self.m;
        m[1] = self.m;
        m[2] = self.j;
        f[0] = self.m * self.g * self.alpha.sin();
        g[(0, 0)] = -s0;
        g[(0, 1)] = s1;
        b[0] = v[2] * (-(v[1] * s0) - v[0] * s1);
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
        (dq, dv)
    }
    #[inline]
    fn constraint_force_jacobians(
        &self,
        q: &::zeitner::__private::Vector<3>,
        v: &::zeitner::__private::Vector<3>,
        t: ::zeitner::__private::Float,
        lambda: &::zeitner::__private::Vector<1>,
    ) -> (::zeitner::__private::Matrix<3, 3>, ::zeitner::__private::Matrix<3, 3>) {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let mut dq = ::zeitner::__private::Matrix::<3, 3>::zeros();
        let mut dv = ::zeitner::__private::Matrix::<3, 3>::zeros();
        dq[(0, 2)] = -(q[2].cos() * lambda[0]);
        dq[(1, 2)] = -(q[2].sin() * lambda[0]);
        (dq, dv)
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
        values[0] = -q[2].sin();
        values[1] = q[2].cos();
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
    }
    #[inline]
    fn constraint_force_jacobian_nonzeros(
        &self,
        q: &::zeitner::__private::Vector<3>,
        v: &::zeitner::__private::Vector<3>,
        t: ::zeitner::__private::Float,
        lambda: &::zeitner::__private::Vector<1>,
        values: &mut [::zeitner::__private::Float],
    ) {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        values[0] = -(q[2].cos() * lambda[0]);
        values[1] = -(q[2].sin() * lambda[0]);
    }
}
#[allow(unused_variables, unused_mut, clippy::all)]
impl ::zeitner::__private::ParametrisedSystem<3, 1, 3> for KnifeEdge {
    const PARAMETER_NAMES: [&'static str; 3] = ["alpha", "g", "m"];
    #[inline]
    fn parameter_values(&self) -> ::zeitner::__private::Vector<3> {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let mut theta = ::zeitner::__private::Vector::<3>::zeros();
        theta[0] = self.alpha;
        theta[1] = self.g;
        theta[2] = self.m;
        theta
    }
    #[inline]
    fn parameter_force(
        &self,
        q: &::zeitner::__private::Vector<3>,
        v: &::zeitner::__private::Vector<3>,
        t: ::zeitner::__private::Float,
        lambda: &::zeitner::__private::Vector<1>,
        a: &::zeitner::__private::Vector<3>,
    ) -> ::zeitner::__private::Matrix<3, 3> {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let s0 = self.alpha.sin();
        let mut df = ::zeitner::__private::Matrix::<3, 3>::zeros();
        df[(0, 0)] = self.m * self.g * self.alpha.cos();
        df[(0, 1)] = self.m * s0;
        df[(0, 2)] = self.g * s0 - a[0];
        df[(1, 2)] = -a[1];
        df
    }
    #[inline]
    fn parameter_constraints(
        &self,
        q: &::zeitner::__private::Vector<3>,
        v: &::zeitner::__private::Vector<3>,
        t: ::zeitner::__private::Float,
    ) -> (::zeitner::__private::Matrix<1, 3>, ::zeitner::__private::Matrix<1, 3>) {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let mut dg = ::zeitner::__private::Matrix::<1, 3>::zeros();
        let mut dw = ::zeitner::__private::Matrix::<1, 3>::zeros();
        (dg, dw)
    }
    #[inline]
    fn rate_jacobians(
        &self,
        q: &::zeitner::__private::Vector<3>,
        v: &::zeitner::__private::Vector<3>,
        t: ::zeitner::__private::Float,
    ) -> (::zeitner::__private::Matrix<1, 3>, ::zeitner::__private::Matrix<1, 3>) {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let s0 = q[2].sin();
        let s1 = q[2].cos();
        let mut wq = ::zeitner::__private::Matrix::<1, 3>::zeros();
        let mut wv = ::zeitner::__private::Matrix::<1, 3>::zeros();
        wq[(0, 2)] = -(v[1] * s0) - v[0] * s1;
        wv[(0, 0)] = -s0;
        wv[(0, 1)] = s1;
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
        ::zeitner::__private::Matrix<1, 3>,
        ::zeitner::__private::Matrix<1, 3>,
        ::zeitner::__private::Matrix<1, 3>,
    ) {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let s0 = q[2].sin();
        let s1 = q[2].cos();
        let mut cq = ::zeitner::__private::Matrix::<1, 3>::zeros();
        let mut cv = ::zeitner::__private::Matrix::<1, 3>::zeros();
        let mut cp = ::zeitner::__private::Matrix::<1, 3>::zeros();
        cq[(0, 2)] = v[2] * (v[0] * s0 - v[1] * s1) - s1 * a[0] - s0 * a[1];
        cv[(0, 0)] = -(v[2] * s1);
        cv[(0, 1)] = -(v[2] * s0);
        cv[(0, 2)] = -(v[1] * s0) - v[0] * s1;
        (cq, cv, cp)
    }
}
#[allow(dead_code)]
impl SteeredKnifeEdge {
    fn mass(&self) -> [Float; 3] {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        [self.edge.m, self.edge.m, self.edge.j]
    }
    fn force(&self) -> [Float; 3] {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        [self.edge.m * self.edge.g * self.edge.alpha.sin(), 0.0, self.torque]
    }
    fn constraints(&self, [_x, _y, theta]: [Float; 3], t: Float) -> [Float; 1] {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        [theta - self.omega * t]
    }
    fn velocity_constraints(
        &self,
        [_x,
        _y,
        theta,
        ]: [Float; 3],
        [vx,
        vy,
        _w,
        ]: [Float; 3],
    ) -> [Float; 1] {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        [-theta.sin() * vx + theta.cos() * vy]
    }
    /// For sensitivities: the slope, the steering rate and the torque.
    fn parameters(&self) -> [Float; 3] {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        [self.edge.alpha, self.omega, self.torque]
    }
}
#[allow(unused_variables, unused_mut, clippy::all)]
impl ::zeitner::__private::ConstrainedSystem<3, 2> for SteeredKnifeEdge {
    const POSITION_CONSTRAINTS: usize = 1;
    const MASS_IS_CONSTANT: bool = true;
    const DYNAMICS_DEPEND_ON_VELOCITY: bool = false;
    const SUMMARY: ::zeitner::__private::SceneSummary = ::zeitner::__private::SceneSummary {
        coordinates: 3,
        position_constraints: 1,
        velocity_constraints: 1,
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
                        nonzeros: &[(0, 0), (2, 0)],
                    },
                ],
                ops: ::zeitner::__private::OpCounts {
                    adds: 0u64,
                    muls: 2u64,
                    divs: 0u64,
                    transcendental: 1u64,
                    opaque_calls: 0u64,
                },
                ops_unshared: ::zeitner::__private::OpCounts {
                    adds: 0u64,
                    muls: 2u64,
                    divs: 0u64,
                    transcendental: 1u64,
                    opaque_calls: 0u64,
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
                    adds: 2u64,
                    muls: 3u64,
                    divs: 0u64,
                    transcendental: 2u64,
                    opaque_calls: 0u64,
                },
                ops_unshared: ::zeitner::__private::OpCounts {
                    adds: 2u64,
                    muls: 3u64,
                    divs: 0u64,
                    transcendental: 2u64,
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
                        nonzeros: &[(0, 2), (1, 0), (1, 1)],
                    },
                ],
                ops: ::zeitner::__private::OpCounts {
                    adds: 1u64,
                    muls: 0u64,
                    divs: 0u64,
                    transcendental: 2u64,
                    opaque_calls: 0u64,
                },
                ops_unshared: ::zeitner::__private::OpCounts {
                    adds: 1u64,
                    muls: 0u64,
                    divs: 0u64,
                    transcendental: 2u64,
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
                        nonzeros: &[(0, 2), (1, 2)],
                    },
                ],
                ops: ::zeitner::__private::OpCounts {
                    adds: 2u64,
                    muls: 2u64,
                    divs: 0u64,
                    transcendental: 2u64,
                    opaque_calls: 0u64,
                },
                ops_unshared: ::zeitner::__private::OpCounts {
                    adds: 2u64,
                    muls: 2u64,
                    divs: 0u64,
                    transcendental: 2u64,
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
                    adds: 2u64,
                    muls: 2u64,
                    divs: 0u64,
                    transcendental: 2u64,
                    opaque_calls: 0u64,
                },
                ops_unshared: ::zeitner::__private::OpCounts {
                    adds: 2u64,
                    muls: 2u64,
                    divs: 0u64,
                    transcendental: 2u64,
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
                    adds: 2u64,
                    muls: 3u64,
                    divs: 0u64,
                    transcendental: 2u64,
                    opaque_calls: 0u64,
                },
                ops_unshared: ::zeitner::__private::OpCounts {
                    adds: 2u64,
                    muls: 3u64,
                    divs: 0u64,
                    transcendental: 2u64,
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
                        nonzeros: &[(0, 0), (2, 0)],
                    },
                    ::zeitner::__private::BlockSummary {
                        name: "g",
                        rows: 2,
                        cols: 3,
                        nonzeros: &[(0, 2), (1, 0), (1, 1)],
                    },
                    ::zeitner::__private::BlockSummary {
                        name: "b",
                        rows: 2,
                        cols: 1,
                        nonzeros: &[(1, 0)],
                    },
                ],
                ops: ::zeitner::__private::OpCounts {
                    adds: 3u64,
                    muls: 5u64,
                    divs: 0u64,
                    transcendental: 3u64,
                    opaque_calls: 0u64,
                },
                ops_unshared: ::zeitner::__private::OpCounts {
                    adds: 3u64,
                    muls: 5u64,
                    divs: 0u64,
                    transcendental: 5u64,
                    opaque_calls: 0u64,
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
                        rows: 3,
                        cols: 3,
                        nonzeros: &[(0, 2), (1, 2)],
                    },
                    ::zeitner::__private::BlockSummary {
                        name: "dv",
                        rows: 3,
                        cols: 3,
                        nonzeros: &[],
                    },
                ],
                ops: ::zeitner::__private::OpCounts {
                    adds: 2u64,
                    muls: 2u64,
                    divs: 0u64,
                    transcendental: 2u64,
                    opaque_calls: 0u64,
                },
                ops_unshared: ::zeitner::__private::OpCounts {
                    adds: 2u64,
                    muls: 2u64,
                    divs: 0u64,
                    transcendental: 2u64,
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
                        nonzeros: &[(1, 2)],
                    },
                    ::zeitner::__private::BlockSummary {
                        name: "wv",
                        rows: 2,
                        cols: 3,
                        nonzeros: &[(0, 2), (1, 0), (1, 1)],
                    },
                ],
                ops: ::zeitner::__private::OpCounts {
                    adds: 3u64,
                    muls: 2u64,
                    divs: 0u64,
                    transcendental: 2u64,
                    opaque_calls: 0u64,
                },
                ops_unshared: ::zeitner::__private::OpCounts {
                    adds: 3u64,
                    muls: 2u64,
                    divs: 0u64,
                    transcendental: 4u64,
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
                        nonzeros: &[(1, 2)],
                    },
                    ::zeitner::__private::BlockSummary {
                        name: "cv",
                        rows: 2,
                        cols: 3,
                        nonzeros: &[(1, 0), (1, 1), (1, 2)],
                    },
                    ::zeitner::__private::BlockSummary {
                        name: "cp",
                        rows: 2,
                        cols: 3,
                        nonzeros: &[],
                    },
                ],
                ops: ::zeitner::__private::OpCounts {
                    adds: 7u64,
                    muls: 9u64,
                    divs: 0u64,
                    transcendental: 2u64,
                    opaque_calls: 0u64,
                },
                ops_unshared: ::zeitner::__private::OpCounts {
                    adds: 7u64,
                    muls: 9u64,
                    divs: 0u64,
                    transcendental: 8u64,
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
                        nonzeros: &[(0, 0), (2, 2)],
                    },
                ],
                ops: ::zeitner::__private::OpCounts {
                    adds: 0u64,
                    muls: 2u64,
                    divs: 0u64,
                    transcendental: 1u64,
                    opaque_calls: 0u64,
                },
                ops_unshared: ::zeitner::__private::OpCounts {
                    adds: 0u64,
                    muls: 2u64,
                    divs: 0u64,
                    transcendental: 1u64,
                    opaque_calls: 0u64,
                },
            },
            ::zeitner::__private::FunctionSummary {
                name: "parameter_constraints",
                blocks: &[
                    ::zeitner::__private::BlockSummary {
                        name: "dg",
                        rows: 2,
                        cols: 3,
                        nonzeros: &[(0, 1)],
                    },
                    ::zeitner::__private::BlockSummary {
                        name: "dw",
                        rows: 2,
                        cols: 3,
                        nonzeros: &[(0, 1)],
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
        ],
    };
    type Mass = ::zeitner::__private::DiagonalMass<3>;
    type Storage = ::zeitner::__private::Dense;
    const SPARSITY: ::core::option::Option<::zeitner::__private::Sparsity> = ::core::option::Option::Some(::zeitner::__private::Sparsity {
        constraint_jacobian: &[(0, 2), (1, 0), (1, 1)],
        force_jacobians: [&[], &[]],
        constraint_force_jacobians: [&[(0, 2), (1, 2)], &[]],
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
        m[0] = self.edge.m;
        m[1] = self.edge.m;
        m[2] = self.edge.j;
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
        let mut f = ::zeitner::__private::Vector::<3>::zeros();
        f[0] = self.edge.m * self.edge.g * self.edge.alpha.sin();
        f[2] = self.torque;
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
        g[0] = q[2] - t * self.omega;
        g[1] = v[1] * q[2].cos() - v[0] * q[2].sin();
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
        g[(0, 2)] = 1.0;
        g[(1, 0)] = -q[2].sin();
        g[(1, 1)] = q[2].cos();
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
        p[(0, 2)] = 1.0;
        p[(1, 2)] = -(v[1] * q[2].sin()) - v[0] * q[2].cos();
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
        w[0] = v[2] - self.omega;
        w[1] = v[1] * q[2].cos() - v[0] * q[2].sin();
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
        b[1] = v[2] * (-(v[1] * q[2].sin()) - v[0] * q[2].cos());
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
        let s0 = q[2].sin();
        let s1 = q[2].cos();
        let mut m = ::zeitner::__private::Vector::<3>::zeros();
        let mut f = ::zeitner::__private::Vector::<3>::zeros();
        let mut g = ::zeitner::__private::Matrix::<2, 3>::zeros();
        let mut b = ::zeitner::__private::Vector::<2>::zeros();
        m[0] = self.edge.m;
        m[1] = self.edge.m;
        m[2] = self.edge.j;
        f[0] = self.edge.m * self.edge.g * self.edge.alpha.sin();
        f[2] = self.torque;
        g[(0, 2)] = 1.0;
        g[(1, 0)] = -s0;
        g[(1, 1)] = s1;
        b[1] = v[2] * (-(v[1] * s0) - v[0] * s1);
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
        let mut dq = ::zeitner::__private::Matrix::<3, 3>::zeros();
        let mut dv = ::zeitner::__private::Matrix::<3, 3>::zeros();
        dq[(0, 2)] = -(q[2].cos() * lambda[1]);
        dq[(1, 2)] = -(q[2].sin() * lambda[1]);
        (dq, dv)
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
        values[1] = -q[2].sin();
        values[2] = q[2].cos();
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
        values[0] = -(q[2].cos() * lambda[1]);
        values[1] = -(q[2].sin() * lambda[1]);
    }
}
#[allow(unused_variables, unused_mut, clippy::all)]
impl ::zeitner::__private::ParametrisedSystem<3, 2, 3> for SteeredKnifeEdge {
    const PARAMETER_NAMES: [&'static str; 3] = ["edge.alpha", "omega", "torque"];
    #[inline]
    fn parameter_values(&self) -> ::zeitner::__private::Vector<3> {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let mut theta = ::zeitner::__private::Vector::<3>::zeros();
        theta[0] = self.edge.alpha;
        theta[1] = self.omega;
        theta[2] = self.torque;
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
    ) -> ::zeitner::__private::Matrix<3, 3> {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let mut df = ::zeitner::__private::Matrix::<3, 3>::zeros();
        df[(0, 0)] = self.edge.m * self.edge.g * self.edge.alpha.cos();
        df[(2, 2)] = 1.0;
        df
    }
    #[inline]
    fn parameter_constraints(
        &self,
        q: &::zeitner::__private::Vector<3>,
        v: &::zeitner::__private::Vector<3>,
        t: ::zeitner::__private::Float,
    ) -> (::zeitner::__private::Matrix<2, 3>, ::zeitner::__private::Matrix<2, 3>) {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let mut dg = ::zeitner::__private::Matrix::<2, 3>::zeros();
        let mut dw = ::zeitner::__private::Matrix::<2, 3>::zeros();
        dg[(0, 1)] = -t;
        dw[(0, 1)] = -1.0;
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
        let s0 = q[2].sin();
        let s1 = q[2].cos();
        let mut wq = ::zeitner::__private::Matrix::<2, 3>::zeros();
        let mut wv = ::zeitner::__private::Matrix::<2, 3>::zeros();
        wq[(1, 2)] = -(v[1] * s0) - v[0] * s1;
        wv[(0, 2)] = 1.0;
        wv[(1, 0)] = -s0;
        wv[(1, 1)] = s1;
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
        ::zeitner::__private::Matrix<2, 3>,
    ) {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let s0 = q[2].sin();
        let s1 = q[2].cos();
        let mut cq = ::zeitner::__private::Matrix::<2, 3>::zeros();
        let mut cv = ::zeitner::__private::Matrix::<2, 3>::zeros();
        let mut cp = ::zeitner::__private::Matrix::<2, 3>::zeros();
        cq[(1, 2)] = v[2] * (v[0] * s0 - v[1] * s1) - s1 * a[0] - s0 * a[1];
        cv[(1, 0)] = -(v[2] * s1);
        cv[(1, 1)] = -(v[2] * s0);
        cv[(1, 2)] = -(v[1] * s0) - v[0] * s1;
        (cq, cv, cp)
    }
}
