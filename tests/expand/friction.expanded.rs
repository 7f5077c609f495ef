#[allow(dead_code)]
impl Incline {
    fn mass(&self) -> [Float; 2] {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        [self.m, self.m]
    }
    fn force(&self) -> [Float; 2] {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        [0.0, -self.m * self.g]
    }
    fn gaps(&self, [x, y]: [Float; 2]) -> [Float; 1] {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        [y * self.angle.cos() - x * self.angle.sin()]
    }
    fn slips(&self, _q: [Float; 2], [vx, vy]: [Float; 2]) -> [Float; 1] {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        [vx * self.angle.cos() + vy * self.angle.sin()]
    }
    fn friction(&self) -> [Float; 1] {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        [self.mu]
    }
}
#[allow(unused_variables, unused_mut, clippy::all)]
impl ::zeitner::__private::ConstrainedSystem<2, 2> for Incline {
    const POSITION_CONSTRAINTS: usize = 1;
    const MASS_IS_CONSTANT: bool = true;
    const DYNAMICS_DEPEND_ON_VELOCITY: bool = false;
    const SUMMARY: ::zeitner::__private::SceneSummary = ::zeitner::__private::SceneSummary {
        coordinates: 2,
        position_constraints: 1,
        velocity_constraints: 1,
        mass: ::zeitner::__private::MassKind::ConstantDiagonal,
        time_dependent: false,
        functions: &[
            ::zeitner::__private::FunctionSummary {
                name: "mass_matrix",
                blocks: &[
                    ::zeitner::__private::BlockSummary {
                        name: "m",
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
                name: "applied_force",
                blocks: &[
                    ::zeitner::__private::BlockSummary {
                        name: "f",
                        rows: 2,
                        cols: 1,
                        nonzeros: &[(1, 0)],
                    },
                ],
                ops: ::zeitner::__private::OpCounts {
                    adds: 1u64,
                    muls: 1u64,
                    divs: 0u64,
                    transcendental: 0u64,
                    opaque_calls: 0u64,
                },
                ops_unshared: ::zeitner::__private::OpCounts {
                    adds: 1u64,
                    muls: 1u64,
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
                        rows: 2,
                        cols: 1,
                        nonzeros: &[(0, 0), (1, 0)],
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
                    transcendental: 4u64,
                    opaque_calls: 0u64,
                },
            },
            ::zeitner::__private::FunctionSummary {
                name: "constraint_jacobian",
                blocks: &[
                    ::zeitner::__private::BlockSummary {
                        name: "g",
                        rows: 2,
                        cols: 2,
                        nonzeros: &[(0, 0), (0, 1), (1, 0), (1, 1)],
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
                    transcendental: 4u64,
                    opaque_calls: 0u64,
                },
            },
            ::zeitner::__private::FunctionSummary {
                name: "constraint_position_partials",
                blocks: &[
                    ::zeitner::__private::BlockSummary {
                        name: "p",
                        rows: 2,
                        cols: 2,
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
                    muls: 4u64,
                    divs: 0u64,
                    transcendental: 2u64,
                    opaque_calls: 0u64,
                },
                ops_unshared: ::zeitner::__private::OpCounts {
                    adds: 2u64,
                    muls: 4u64,
                    divs: 0u64,
                    transcendental: 4u64,
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
                name: "stage",
                blocks: &[
                    ::zeitner::__private::BlockSummary {
                        name: "m",
                        rows: 2,
                        cols: 1,
                        nonzeros: &[(0, 0), (1, 0)],
                    },
                    ::zeitner::__private::BlockSummary {
                        name: "f",
                        rows: 2,
                        cols: 1,
                        nonzeros: &[(1, 0)],
                    },
                    ::zeitner::__private::BlockSummary {
                        name: "g",
                        rows: 2,
                        cols: 2,
                        nonzeros: &[(0, 0), (0, 1), (1, 0), (1, 1)],
                    },
                    ::zeitner::__private::BlockSummary {
                        name: "b",
                        rows: 2,
                        cols: 1,
                        nonzeros: &[],
                    },
                ],
                ops: ::zeitner::__private::OpCounts {
                    adds: 2u64,
                    muls: 1u64,
                    divs: 0u64,
                    transcendental: 2u64,
                    opaque_calls: 0u64,
                },
                ops_unshared: ::zeitner::__private::OpCounts {
                    adds: 2u64,
                    muls: 1u64,
                    divs: 0u64,
                    transcendental: 4u64,
                    opaque_calls: 0u64,
                },
            },
            ::zeitner::__private::FunctionSummary {
                name: "force_jacobians",
                blocks: &[
                    ::zeitner::__private::BlockSummary {
                        name: "dq",
                        rows: 2,
                        cols: 2,
                        nonzeros: &[],
                    },
                    ::zeitner::__private::BlockSummary {
                        name: "dv",
                        rows: 2,
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
            ::zeitner::__private::FunctionSummary {
                name: "constraint_force_jacobians",
                blocks: &[
                    ::zeitner::__private::BlockSummary {
                        name: "dq",
                        rows: 2,
                        cols: 2,
                        nonzeros: &[],
                    },
                    ::zeitner::__private::BlockSummary {
                        name: "dv",
                        rows: 2,
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
            ::zeitner::__private::FunctionSummary {
                name: "friction",
                blocks: &[
                    ::zeitner::__private::BlockSummary {
                        name: "mu",
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
    type Mass = ::zeitner::__private::DiagonalMass<2>;
    type Storage = ::zeitner::__private::Dense;
    const UNILATERAL_CONSTRAINTS: usize = 1usize;
    const SLIDING_CONTACTS: usize = 1usize;
    const SPARSITY: ::core::option::Option<::zeitner::__private::Sparsity> = ::core::option::Option::Some(::zeitner::__private::Sparsity {
        constraint_jacobian: &[(0, 0), (0, 1), (1, 0), (1, 1)],
        force_jacobians: [&[], &[]],
        constraint_force_jacobians: [&[], &[]],
    });
    #[inline]
    fn mass_matrix(
        &self,
        q: &::zeitner::__private::Vector<2>,
        t: ::zeitner::__private::Float,
    ) -> Self::Mass {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let mut m = ::zeitner::__private::Vector::<2>::zeros();
        m[0] = self.m;
        m[1] = self.m;
        ::zeitner::__private::DiagonalMass(m)
    }
    #[inline]
    fn applied_force(
        &self,
        q: &::zeitner::__private::Vector<2>,
        v: &::zeitner::__private::Vector<2>,
        t: ::zeitner::__private::Float,
    ) -> ::zeitner::__private::Vector<2> {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let mut f = ::zeitner::__private::Vector::<2>::zeros();
        f[1] = -(self.m * self.g);
        f
    }
    #[inline]
    fn constraint_residual(
        &self,
        q: &::zeitner::__private::Vector<2>,
        v: &::zeitner::__private::Vector<2>,
        t: ::zeitner::__private::Float,
    ) -> ::zeitner::__private::Vector<2> {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let s0 = self.angle.cos();
        let s1 = self.angle.sin();
        let mut g = ::zeitner::__private::Vector::<2>::zeros();
        g[0] = q[1] * s0 - q[0] * s1;
        g[1] = s0 * v[0] + s1 * v[1];
        g
    }
    #[inline]
    fn constraint_jacobian(
        &self,
        q: &::zeitner::__private::Vector<2>,
        v: &::zeitner::__private::Vector<2>,
        t: ::zeitner::__private::Float,
    ) -> ::zeitner::__private::Matrix<2, 2> {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let s0 = self.angle.cos();
        let s1 = self.angle.sin();
        let mut g = ::zeitner::__private::Matrix::<2, 2>::zeros();
        g[(0, 0)] = -s1;
        g[(0, 1)] = s0;
        g[(1, 0)] = s0;
        g[(1, 1)] = s1;
        g
    }
    #[inline]
    fn constraint_position_partials(
        &self,
        q: &::zeitner::__private::Vector<2>,
        v: &::zeitner::__private::Vector<2>,
        t: ::zeitner::__private::Float,
    ) -> ::zeitner::__private::Matrix<2, 2> {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let mut p = ::zeitner::__private::Matrix::<2, 2>::zeros();
        p[(0, 0)] = -self.angle.sin();
        p[(0, 1)] = self.angle.cos();
        p
    }
    #[inline]
    fn constraint_rate(
        &self,
        q: &::zeitner::__private::Vector<2>,
        v: &::zeitner::__private::Vector<2>,
        t: ::zeitner::__private::Float,
    ) -> ::zeitner::__private::Vector<2> {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let s0 = self.angle.cos();
        let s1 = self.angle.sin();
        let mut w = ::zeitner::__private::Vector::<2>::zeros();
        w[0] = s0 * v[1] - s1 * v[0];
        w[1] = s0 * v[0] + s1 * v[1];
        w
    }
    #[inline]
    fn constraint_acceleration_bias(
        &self,
        q: &::zeitner::__private::Vector<2>,
        v: &::zeitner::__private::Vector<2>,
        t: ::zeitner::__private::Float,
    ) -> ::zeitner::__private::Vector<2> {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let mut b = ::zeitner::__private::Vector::<2>::zeros();
        b
    }
    #[inline]
    fn stage(
        &self,
        q: &::zeitner::__private::Vector<2>,
        v: &::zeitner::__private::Vector<2>,
        t: ::zeitner::__private::Float,
    ) -> (
        Self::Mass,
        ::zeitner::__private::Vector<2>,
        ::zeitner::__private::Matrix<2, 2>,
        ::zeitner::__private::Vector<2>,
    ) {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let s0 = self.angle.cos();
        let s1 = self.angle.sin();
        let mut m = ::zeitner::__private::Vector::<2>::zeros();
        let mut f = ::zeitner::__private::Vector::<2>::zeros();
        let mut g = ::zeitner::__private::Matrix::<2, 2>::zeros();
        let mut b = ::zeitner::__private::Vector::<2>::zeros();
        m[0] = self.m;
        m[1] = self.m;
        f[1] = -(self.m * self.g);
        g[(0, 0)] = -s1;
        g[(0, 1)] = s0;
        g[(1, 0)] = s0;
        g[(1, 1)] = s1;
        (::zeitner::__private::DiagonalMass(m), f, g, b)
    }
    #[inline]
    fn force_jacobians(
        &self,
        q: &::zeitner::__private::Vector<2>,
        v: &::zeitner::__private::Vector<2>,
        t: ::zeitner::__private::Float,
    ) -> (::zeitner::__private::Matrix<2, 2>, ::zeitner::__private::Matrix<2, 2>) {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let mut dq = ::zeitner::__private::Matrix::<2, 2>::zeros();
        let mut dv = ::zeitner::__private::Matrix::<2, 2>::zeros();
        (dq, dv)
    }
    #[inline]
    fn constraint_force_jacobians(
        &self,
        q: &::zeitner::__private::Vector<2>,
        v: &::zeitner::__private::Vector<2>,
        t: ::zeitner::__private::Float,
        lambda: &::zeitner::__private::Vector<2>,
    ) -> (::zeitner::__private::Matrix<2, 2>, ::zeitner::__private::Matrix<2, 2>) {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let mut dq = ::zeitner::__private::Matrix::<2, 2>::zeros();
        let mut dv = ::zeitner::__private::Matrix::<2, 2>::zeros();
        (dq, dv)
    }
    #[inline]
    fn friction(&self, gap: usize) -> ::zeitner::__private::Float {
        let mu = {
            #[allow(unused_imports)]
            use ::zeitner::__private::Real as _;
            let mut mu = ::zeitner::__private::Vector::<1>::zeros();
            mu[0] = self.mu;
            mu
        };
        if gap < 1 { mu[gap] } else { 0.0 }
    }
    #[inline]
    fn constraint_jacobian_nonzeros(
        &self,
        q: &::zeitner::__private::Vector<2>,
        v: &::zeitner::__private::Vector<2>,
        t: ::zeitner::__private::Float,
        values: &mut [::zeitner::__private::Float],
    ) {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let s0 = self.angle.cos();
        let s1 = self.angle.sin();
        values[0] = -s1;
        values[1] = s0;
        values[2] = s0;
        values[3] = s1;
    }
    #[inline]
    fn force_jacobian_nonzeros(
        &self,
        q: &::zeitner::__private::Vector<2>,
        v: &::zeitner::__private::Vector<2>,
        t: ::zeitner::__private::Float,
        values: &mut [::zeitner::__private::Float],
    ) {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
    }
    #[inline]
    fn constraint_force_jacobian_nonzeros(
        &self,
        q: &::zeitner::__private::Vector<2>,
        v: &::zeitner::__private::Vector<2>,
        t: ::zeitner::__private::Float,
        lambda: &::zeitner::__private::Vector<2>,
        values: &mut [::zeitner::__private::Float],
    ) {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
    }
}
#[allow(dead_code)]
impl SlidingOscillator {
    fn mass(&self) -> [Float; 2] {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        [self.m, self.m]
    }
    fn force(&self, [x, _y]: [Float; 2]) -> [Float; 2] {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        [-self.k * x, -self.m * self.g]
    }
    fn gaps(&self, [_x, y]: [Float; 2]) -> [Float; 1] {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        [y]
    }
    fn slips(&self, _q: [Float; 2], [vx, _vy]: [Float; 2]) -> [Float; 1] {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        [vx]
    }
    fn friction(&self) -> [Float; 1] {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        [self.mu]
    }
}
#[allow(unused_variables, unused_mut, clippy::all)]
impl ::zeitner::__private::ConstrainedSystem<2, 2> for SlidingOscillator {
    const POSITION_CONSTRAINTS: usize = 1;
    const MASS_IS_CONSTANT: bool = true;
    const DYNAMICS_DEPEND_ON_VELOCITY: bool = false;
    const SUMMARY: ::zeitner::__private::SceneSummary = ::zeitner::__private::SceneSummary {
        coordinates: 2,
        position_constraints: 1,
        velocity_constraints: 1,
        mass: ::zeitner::__private::MassKind::ConstantDiagonal,
        time_dependent: false,
        functions: &[
            ::zeitner::__private::FunctionSummary {
                name: "mass_matrix",
                blocks: &[
                    ::zeitner::__private::BlockSummary {
                        name: "m",
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
                name: "applied_force",
                blocks: &[
                    ::zeitner::__private::BlockSummary {
                        name: "f",
                        rows: 2,
                        cols: 1,
                        nonzeros: &[(0, 0), (1, 0)],
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
                name: "constraint_jacobian",
                blocks: &[
                    ::zeitner::__private::BlockSummary {
                        name: "g",
                        rows: 2,
                        cols: 2,
                        nonzeros: &[(0, 1), (1, 0)],
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
                name: "constraint_position_partials",
                blocks: &[
                    ::zeitner::__private::BlockSummary {
                        name: "p",
                        rows: 2,
                        cols: 2,
                        nonzeros: &[(0, 1)],
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
                name: "constraint_acceleration_bias",
                blocks: &[
                    ::zeitner::__private::BlockSummary {
                        name: "b",
                        rows: 2,
                        cols: 1,
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
                name: "stage",
                blocks: &[
                    ::zeitner::__private::BlockSummary {
                        name: "m",
                        rows: 2,
                        cols: 1,
                        nonzeros: &[(0, 0), (1, 0)],
                    },
                    ::zeitner::__private::BlockSummary {
                        name: "f",
                        rows: 2,
                        cols: 1,
                        nonzeros: &[(0, 0), (1, 0)],
                    },
                    ::zeitner::__private::BlockSummary {
                        name: "g",
                        rows: 2,
                        cols: 2,
                        nonzeros: &[(0, 1), (1, 0)],
                    },
                    ::zeitner::__private::BlockSummary {
                        name: "b",
                        rows: 2,
                        cols: 1,
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
                    adds: 2u64,
                    muls: 2u64,
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
                        rows: 2,
                        cols: 2,
                        nonzeros: &[(0, 0)],
                    },
                    ::zeitner::__private::BlockSummary {
                        name: "dv",
                        rows: 2,
                        cols: 2,
                        nonzeros: &[],
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
                        rows: 2,
                        cols: 2,
                        nonzeros: &[],
                    },
                    ::zeitner::__private::BlockSummary {
                        name: "dv",
                        rows: 2,
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
            ::zeitner::__private::FunctionSummary {
                name: "friction",
                blocks: &[
                    ::zeitner::__private::BlockSummary {
                        name: "mu",
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
    type Mass = ::zeitner::__private::DiagonalMass<2>;
    type Storage = ::zeitner::__private::Dense;
    const UNILATERAL_CONSTRAINTS: usize = 1usize;
    const SLIDING_CONTACTS: usize = 1usize;
    const SPARSITY: ::core::option::Option<::zeitner::__private::Sparsity> = ::core::option::Option::Some(::zeitner::__private::Sparsity {
        constraint_jacobian: &[(0, 1), (1, 0)],
        force_jacobians: [&[(0, 0)], &[]],
        constraint_force_jacobians: [&[], &[]],
    });
    #[inline]
    fn mass_matrix(
        &self,
        q: &::zeitner::__private::Vector<2>,
        t: ::zeitner::__private::Float,
    ) -> Self::Mass {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let mut m = ::zeitner::__private::Vector::<2>::zeros();
        m[0] = self.m;
        m[1] = self.m;
        ::zeitner::__private::DiagonalMass(m)
    }
    #[inline]
    fn applied_force(
        &self,
        q: &::zeitner::__private::Vector<2>,
        v: &::zeitner::__private::Vector<2>,
        t: ::zeitner::__private::Float,
    ) -> ::zeitner::__private::Vector<2> {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let mut f = ::zeitner::__private::Vector::<2>::zeros();
        f[0] = -(q[0] * self.k);
        f[1] = -(self.m * self.g);
        f
    }
    #[inline]
    fn constraint_residual(
        &self,
        q: &::zeitner::__private::Vector<2>,
        v: &::zeitner::__private::Vector<2>,
        t: ::zeitner::__private::Float,
    ) -> ::zeitner::__private::Vector<2> {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let mut g = ::zeitner::__private::Vector::<2>::zeros();
        g[0] = q[1];
        g[1] = v[0];
        g
    }
    #[inline]
    fn constraint_jacobian(
        &self,
        q: &::zeitner::__private::Vector<2>,
        v: &::zeitner::__private::Vector<2>,
        t: ::zeitner::__private::Float,
    ) -> ::zeitner::__private::Matrix<2, 2> {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let mut g = ::zeitner::__private::Matrix::<2, 2>::zeros();
        g[(0, 1)] = 1.0;
        g[(1, 0)] = 1.0;
        g
    }
    #[inline]
    fn constraint_position_partials(
        &self,
        q: &::zeitner::__private::Vector<2>,
        v: &::zeitner::__private::Vector<2>,
        t: ::zeitner::__private::Float,
    ) -> ::zeitner::__private::Matrix<2, 2> {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let mut p = ::zeitner::__private::Matrix::<2, 2>::zeros();
        p[(0, 1)] = 1.0;
        p
    }
    #[inline]
    fn constraint_rate(
        &self,
        q: &::zeitner::__private::Vector<2>,
        v: &::zeitner::__private::Vector<2>,
        t: ::zeitner::__private::Float,
    ) -> ::zeitner::__private::Vector<2> {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let mut w = ::zeitner::__private::Vector::<2>::zeros();
        w[0] = v[1];
        w[1] = v[0];
        w
    }
    #[inline]
    fn constraint_acceleration_bias(
        &self,
        q: &::zeitner::__private::Vector<2>,
        v: &::zeitner::__private::Vector<2>,
        t: ::zeitner::__private::Float,
    ) -> ::zeitner::__private::Vector<2> {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let mut b = ::zeitner::__private::Vector::<2>::zeros();
        b
    }
    #[inline]
    fn stage(
        &self,
        q: &::zeitner::__private::Vector<2>,
        v: &::zeitner::__private::Vector<2>,
        t: ::zeitner::__private::Float,
    ) -> (
        Self::Mass,
        ::zeitner::__private::Vector<2>,
        ::zeitner::__private::Matrix<2, 2>,
        ::zeitner::__private::Vector<2>,
    ) {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let mut m = ::zeitner::__private::Vector::<2>::zeros();
        let mut f = ::zeitner::__private::Vector::<2>::zeros();
        let mut g = ::zeitner::__private::Matrix::<2, 2>::zeros();
        let mut b = ::zeitner::__private::Vector::<2>::zeros();
        m[0] = self.m;
        m[1] = self.m;
        f[0] = -(q[0] * self.k);
        f[1] = -(self.m * self.g);
        g[(0, 1)] = 1.0;
        g[(1, 0)] = 1.0;
        (::zeitner::__private::DiagonalMass(m), f, g, b)
    }
    #[inline]
    fn force_jacobians(
        &self,
        q: &::zeitner::__private::Vector<2>,
        v: &::zeitner::__private::Vector<2>,
        t: ::zeitner::__private::Float,
    ) -> (::zeitner::__private::Matrix<2, 2>, ::zeitner::__private::Matrix<2, 2>) {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let mut dq = ::zeitner::__private::Matrix::<2, 2>::zeros();
        let mut dv = ::zeitner::__private::Matrix::<2, 2>::zeros();
        dq[(0, 0)] = -self.k;
        (dq, dv)
    }
    #[inline]
    fn constraint_force_jacobians(
        &self,
        q: &::zeitner::__private::Vector<2>,
        v: &::zeitner::__private::Vector<2>,
        t: ::zeitner::__private::Float,
        lambda: &::zeitner::__private::Vector<2>,
    ) -> (::zeitner::__private::Matrix<2, 2>, ::zeitner::__private::Matrix<2, 2>) {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let mut dq = ::zeitner::__private::Matrix::<2, 2>::zeros();
        let mut dv = ::zeitner::__private::Matrix::<2, 2>::zeros();
        (dq, dv)
    }
    #[inline]
    fn friction(&self, gap: usize) -> ::zeitner::__private::Float {
        let mu = {
            #[allow(unused_imports)]
            use ::zeitner::__private::Real as _;
            let mut mu = ::zeitner::__private::Vector::<1>::zeros();
            mu[0] = self.mu;
            mu
        };
        if gap < 1 { mu[gap] } else { 0.0 }
    }
    #[inline]
    fn constraint_jacobian_nonzeros(
        &self,
        q: &::zeitner::__private::Vector<2>,
        v: &::zeitner::__private::Vector<2>,
        t: ::zeitner::__private::Float,
        values: &mut [::zeitner::__private::Float],
    ) {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        values[0] = 1.0;
        values[1] = 1.0;
    }
    #[inline]
    fn force_jacobian_nonzeros(
        &self,
        q: &::zeitner::__private::Vector<2>,
        v: &::zeitner::__private::Vector<2>,
        t: ::zeitner::__private::Float,
        values: &mut [::zeitner::__private::Float],
    ) {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        values[0] = -self.k;
    }
    #[inline]
    fn constraint_force_jacobian_nonzeros(
        &self,
        q: &::zeitner::__private::Vector<2>,
        v: &::zeitner::__private::Vector<2>,
        t: ::zeitner::__private::Float,
        lambda: &::zeitner::__private::Vector<2>,
        values: &mut [::zeitner::__private::Float],
    ) {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
    }
}
#[allow(dead_code)]
impl Belt {
    fn mass(&self) -> [Float; 2] {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        [self.m, self.m]
    }
    fn force(&self, [x, _y]: [Float; 2]) -> [Float; 2] {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        [-self.k * x, -self.m * self.g]
    }
    fn gaps(&self, [_x, y]: [Float; 2]) -> [Float; 1] {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        [y]
    }
    fn slips(&self, _q: [Float; 2], [vx, _vy]: [Float; 2]) -> [Float; 1] {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        [vx - self.belt]
    }
    fn friction(&self) -> [Float; 1] {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        [self.mu]
    }
}
#[allow(unused_variables, unused_mut, clippy::all)]
impl ::zeitner::__private::ConstrainedSystem<2, 2> for Belt {
    const POSITION_CONSTRAINTS: usize = 1;
    const MASS_IS_CONSTANT: bool = true;
    const DYNAMICS_DEPEND_ON_VELOCITY: bool = false;
    const SUMMARY: ::zeitner::__private::SceneSummary = ::zeitner::__private::SceneSummary {
        coordinates: 2,
        position_constraints: 1,
        velocity_constraints: 1,
        mass: ::zeitner::__private::MassKind::ConstantDiagonal,
        time_dependent: false,
        functions: &[
            ::zeitner::__private::FunctionSummary {
                name: "mass_matrix",
                blocks: &[
                    ::zeitner::__private::BlockSummary {
                        name: "m",
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
                name: "applied_force",
                blocks: &[
                    ::zeitner::__private::BlockSummary {
                        name: "f",
                        rows: 2,
                        cols: 1,
                        nonzeros: &[(0, 0), (1, 0)],
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
                        rows: 2,
                        cols: 1,
                        nonzeros: &[(0, 0), (1, 0)],
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
                name: "constraint_jacobian",
                blocks: &[
                    ::zeitner::__private::BlockSummary {
                        name: "g",
                        rows: 2,
                        cols: 2,
                        nonzeros: &[(0, 1), (1, 0)],
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
                name: "constraint_position_partials",
                blocks: &[
                    ::zeitner::__private::BlockSummary {
                        name: "p",
                        rows: 2,
                        cols: 2,
                        nonzeros: &[(0, 1)],
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
                name: "constraint_acceleration_bias",
                blocks: &[
                    ::zeitner::__private::BlockSummary {
                        name: "b",
                        rows: 2,
                        cols: 1,
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
                name: "stage",
                blocks: &[
                    ::zeitner::__private::BlockSummary {
                        name: "m",
                        rows: 2,
                        cols: 1,
                        nonzeros: &[(0, 0), (1, 0)],
                    },
                    ::zeitner::__private::BlockSummary {
                        name: "f",
                        rows: 2,
                        cols: 1,
                        nonzeros: &[(0, 0), (1, 0)],
                    },
                    ::zeitner::__private::BlockSummary {
                        name: "g",
                        rows: 2,
                        cols: 2,
                        nonzeros: &[(0, 1), (1, 0)],
                    },
                    ::zeitner::__private::BlockSummary {
                        name: "b",
                        rows: 2,
                        cols: 1,
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
                    adds: 2u64,
                    muls: 2u64,
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
                        rows: 2,
                        cols: 2,
                        nonzeros: &[(0, 0)],
                    },
                    ::zeitner::__private::BlockSummary {
                        name: "dv",
                        rows: 2,
                        cols: 2,
                        nonzeros: &[],
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
                        rows: 2,
                        cols: 2,
                        nonzeros: &[],
                    },
                    ::zeitner::__private::BlockSummary {
                        name: "dv",
                        rows: 2,
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
            ::zeitner::__private::FunctionSummary {
                name: "friction",
                blocks: &[
                    ::zeitner::__private::BlockSummary {
                        name: "mu",
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
    type Mass = ::zeitner::__private::DiagonalMass<2>;
    type Storage = ::zeitner::__private::Dense;
    const UNILATERAL_CONSTRAINTS: usize = 1usize;
    const SLIDING_CONTACTS: usize = 1usize;
    const SPARSITY: ::core::option::Option<::zeitner::__private::Sparsity> = ::core::option::Option::Some(::zeitner::__private::Sparsity {
        constraint_jacobian: &[(0, 1), (1, 0)],
        force_jacobians: [&[(0, 0)], &[]],
        constraint_force_jacobians: [&[], &[]],
    });
    #[inline]
    fn mass_matrix(
        &self,
        q: &::zeitner::__private::Vector<2>,
        t: ::zeitner::__private::Float,
    ) -> Self::Mass {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let mut m = ::zeitner::__private::Vector::<2>::zeros();
        m[0] = self.m;
        m[1] = self.m;
        ::zeitner::__private::DiagonalMass(m)
    }
    #[inline]
    fn applied_force(
        &self,
        q: &::zeitner::__private::Vector<2>,
        v: &::zeitner::__private::Vector<2>,
        t: ::zeitner::__private::Float,
    ) -> ::zeitner::__private::Vector<2> {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let mut f = ::zeitner::__private::Vector::<2>::zeros();
        f[0] = -(q[0] * self.k);
        f[1] = -(self.m * self.g);
        f
    }
    #[inline]
    fn constraint_residual(
        &self,
        q: &::zeitner::__private::Vector<2>,
        v: &::zeitner::__private::Vector<2>,
        t: ::zeitner::__private::Float,
    ) -> ::zeitner::__private::Vector<2> {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let mut g = ::zeitner::__private::Vector::<2>::zeros();
        g[0] = q[1];
        g[1] = v[0] - self.belt;
        g
    }
    #[inline]
    fn constraint_jacobian(
        &self,
        q: &::zeitner::__private::Vector<2>,
        v: &::zeitner::__private::Vector<2>,
        t: ::zeitner::__private::Float,
    ) -> ::zeitner::__private::Matrix<2, 2> {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let mut g = ::zeitner::__private::Matrix::<2, 2>::zeros();
        g[(0, 1)] = 1.0;
        g[(1, 0)] = 1.0;
        g
    }
    #[inline]
    fn constraint_position_partials(
        &self,
        q: &::zeitner::__private::Vector<2>,
        v: &::zeitner::__private::Vector<2>,
        t: ::zeitner::__private::Float,
    ) -> ::zeitner::__private::Matrix<2, 2> {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let mut p = ::zeitner::__private::Matrix::<2, 2>::zeros();
        p[(0, 1)] = 1.0;
        p
    }
    #[inline]
    fn constraint_rate(
        &self,
        q: &::zeitner::__private::Vector<2>,
        v: &::zeitner::__private::Vector<2>,
        t: ::zeitner::__private::Float,
    ) -> ::zeitner::__private::Vector<2> {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let mut w = ::zeitner::__private::Vector::<2>::zeros();
        w[0] = v[1];
        w[1] = v[0] - self.belt;
        w
    }
    #[inline]
    fn constraint_acceleration_bias(
        &self,
        q: &::zeitner::__private::Vector<2>,
        v: &::zeitner::__private::Vector<2>,
        t: ::zeitner::__private::Float,
    ) -> ::zeitner::__private::Vector<2> {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let mut b = ::zeitner::__private::Vector::<2>::zeros();
        b
    }
    #[inline]
    fn stage(
        &self,
        q: &::zeitner::__private::Vector<2>,
        v: &::zeitner::__private::Vector<2>,
        t: ::zeitner::__private::Float,
    ) -> (
        Self::Mass,
        ::zeitner::__private::Vector<2>,
        ::zeitner::__private::Matrix<2, 2>,
        ::zeitner::__private::Vector<2>,
    ) {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let mut m = ::zeitner::__private::Vector::<2>::zeros();
        let mut f = ::zeitner::__private::Vector::<2>::zeros();
        let mut g = ::zeitner::__private::Matrix::<2, 2>::zeros();
        let mut b = ::zeitner::__private::Vector::<2>::zeros();
        m[0] = self.m;
        m[1] = self.m;
        f[0] = -(q[0] * self.k);
        f[1] = -(self.m * self.g);
        g[(0, 1)] = 1.0;
        g[(1, 0)] = 1.0;
        (::zeitner::__private::DiagonalMass(m), f, g, b)
    }
    #[inline]
    fn force_jacobians(
        &self,
        q: &::zeitner::__private::Vector<2>,
        v: &::zeitner::__private::Vector<2>,
        t: ::zeitner::__private::Float,
    ) -> (::zeitner::__private::Matrix<2, 2>, ::zeitner::__private::Matrix<2, 2>) {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let mut dq = ::zeitner::__private::Matrix::<2, 2>::zeros();
        let mut dv = ::zeitner::__private::Matrix::<2, 2>::zeros();
        dq[(0, 0)] = -self.k;
        (dq, dv)
    }
    #[inline]
    fn constraint_force_jacobians(
        &self,
        q: &::zeitner::__private::Vector<2>,
        v: &::zeitner::__private::Vector<2>,
        t: ::zeitner::__private::Float,
        lambda: &::zeitner::__private::Vector<2>,
    ) -> (::zeitner::__private::Matrix<2, 2>, ::zeitner::__private::Matrix<2, 2>) {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let mut dq = ::zeitner::__private::Matrix::<2, 2>::zeros();
        let mut dv = ::zeitner::__private::Matrix::<2, 2>::zeros();
        (dq, dv)
    }
    #[inline]
    fn friction(&self, gap: usize) -> ::zeitner::__private::Float {
        let mu = {
            #[allow(unused_imports)]
            use ::zeitner::__private::Real as _;
            let mut mu = ::zeitner::__private::Vector::<1>::zeros();
            mu[0] = self.mu;
            mu
        };
        if gap < 1 { mu[gap] } else { 0.0 }
    }
    #[inline]
    fn constraint_jacobian_nonzeros(
        &self,
        q: &::zeitner::__private::Vector<2>,
        v: &::zeitner::__private::Vector<2>,
        t: ::zeitner::__private::Float,
        values: &mut [::zeitner::__private::Float],
    ) {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        values[0] = 1.0;
        values[1] = 1.0;
    }
    #[inline]
    fn force_jacobian_nonzeros(
        &self,
        q: &::zeitner::__private::Vector<2>,
        v: &::zeitner::__private::Vector<2>,
        t: ::zeitner::__private::Float,
        values: &mut [::zeitner::__private::Float],
    ) {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        values[0] = -self.k;
    }
    #[inline]
    fn constraint_force_jacobian_nonzeros(
        &self,
        q: &::zeitner::__private::Vector<2>,
        v: &::zeitner::__private::Vector<2>,
        t: ::zeitner::__private::Float,
        lambda: &::zeitner::__private::Vector<2>,
        values: &mut [::zeitner::__private::Float],
    ) {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
    }
}
#[allow(dead_code)]
impl PainleveRod {
    fn mass(&self) -> [Float; 3] {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        [self.m, self.m, self.m * self.l * self.l / 3.0]
    }
    fn force(&self) -> [Float; 3] {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        [0.0, -self.m * self.g, 0.0]
    }
    fn gaps(&self, [_x, y, th]: [Float; 3]) -> [Float; 2] {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        [self.ceiling - y - self.l * th.sin(), y - self.l * th.sin()]
    }
    fn slips(&self, [_x, _y, th]: [Float; 3], [vx, _vy, w]: [Float; 3]) -> [Float; 2] {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        [vx - self.l * th.sin() * w, vx + self.l * th.sin() * w]
    }
    fn friction(&self) -> [Float; 2] {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        [self.mu, self.mu]
    }
}
#[allow(unused_variables, unused_mut, clippy::all)]
impl ::zeitner::__private::ConstrainedSystem<3, 4> for PainleveRod {
    const POSITION_CONSTRAINTS: usize = 2;
    const MASS_IS_CONSTANT: bool = true;
    const DYNAMICS_DEPEND_ON_VELOCITY: bool = false;
    const SUMMARY: ::zeitner::__private::SceneSummary = ::zeitner::__private::SceneSummary {
        coordinates: 3,
        position_constraints: 2,
        velocity_constraints: 2,
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
                    muls: 2u64,
                    divs: 1u64,
                    transcendental: 0u64,
                    opaque_calls: 0u64,
                },
                ops_unshared: ::zeitner::__private::OpCounts {
                    adds: 0u64,
                    muls: 2u64,
                    divs: 1u64,
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
                        nonzeros: &[(1, 0)],
                    },
                ],
                ops: ::zeitner::__private::OpCounts {
                    adds: 1u64,
                    muls: 1u64,
                    divs: 0u64,
                    transcendental: 0u64,
                    opaque_calls: 0u64,
                },
                ops_unshared: ::zeitner::__private::OpCounts {
                    adds: 1u64,
                    muls: 1u64,
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
                        rows: 4,
                        cols: 1,
                        nonzeros: &[(0, 0), (1, 0), (2, 0), (3, 0)],
                    },
                ],
                ops: ::zeitner::__private::OpCounts {
                    adds: 5u64,
                    muls: 2u64,
                    divs: 0u64,
                    transcendental: 1u64,
                    opaque_calls: 0u64,
                },
                ops_unshared: ::zeitner::__private::OpCounts {
                    adds: 5u64,
                    muls: 6u64,
                    divs: 0u64,
                    transcendental: 4u64,
                    opaque_calls: 0u64,
                },
            },
            ::zeitner::__private::FunctionSummary {
                name: "constraint_jacobian",
                blocks: &[
                    ::zeitner::__private::BlockSummary {
                        name: "g",
                        rows: 4,
                        cols: 3,
                        nonzeros: &[
                            (0, 1),
                            (0, 2),
                            (1, 1),
                            (1, 2),
                            (2, 0),
                            (2, 2),
                            (3, 0),
                            (3, 2),
                        ],
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
                    adds: 3u64,
                    muls: 4u64,
                    divs: 0u64,
                    transcendental: 4u64,
                    opaque_calls: 0u64,
                },
            },
            ::zeitner::__private::FunctionSummary {
                name: "constraint_position_partials",
                blocks: &[
                    ::zeitner::__private::BlockSummary {
                        name: "p",
                        rows: 4,
                        cols: 3,
                        nonzeros: &[(0, 1), (0, 2), (1, 1), (1, 2), (2, 2), (3, 2)],
                    },
                ],
                ops: ::zeitner::__private::OpCounts {
                    adds: 2u64,
                    muls: 2u64,
                    divs: 0u64,
                    transcendental: 1u64,
                    opaque_calls: 0u64,
                },
                ops_unshared: ::zeitner::__private::OpCounts {
                    adds: 3u64,
                    muls: 6u64,
                    divs: 0u64,
                    transcendental: 4u64,
                    opaque_calls: 0u64,
                },
            },
            ::zeitner::__private::FunctionSummary {
                name: "constraint_rate",
                blocks: &[
                    ::zeitner::__private::BlockSummary {
                        name: "w",
                        rows: 4,
                        cols: 1,
                        nonzeros: &[(0, 0), (1, 0), (2, 0), (3, 0)],
                    },
                ],
                ops: ::zeitner::__private::OpCounts {
                    adds: 5u64,
                    muls: 4u64,
                    divs: 0u64,
                    transcendental: 2u64,
                    opaque_calls: 0u64,
                },
                ops_unshared: ::zeitner::__private::OpCounts {
                    adds: 5u64,
                    muls: 8u64,
                    divs: 0u64,
                    transcendental: 4u64,
                    opaque_calls: 0u64,
                },
            },
            ::zeitner::__private::FunctionSummary {
                name: "constraint_acceleration_bias",
                blocks: &[
                    ::zeitner::__private::BlockSummary {
                        name: "b",
                        rows: 4,
                        cols: 1,
                        nonzeros: &[(0, 0), (1, 0), (2, 0), (3, 0)],
                    },
                ],
                ops: ::zeitner::__private::OpCounts {
                    adds: 1u64,
                    muls: 6u64,
                    divs: 0u64,
                    transcendental: 2u64,
                    opaque_calls: 0u64,
                },
                ops_unshared: ::zeitner::__private::OpCounts {
                    adds: 1u64,
                    muls: 12u64,
                    divs: 0u64,
                    transcendental: 4u64,
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
                        nonzeros: &[(1, 0)],
                    },
                    ::zeitner::__private::BlockSummary {
                        name: "g",
                        rows: 4,
                        cols: 3,
                        nonzeros: &[
                            (0, 1),
                            (0, 2),
                            (1, 1),
                            (1, 2),
                            (2, 0),
                            (2, 2),
                            (3, 0),
                            (3, 2),
                        ],
                    },
                    ::zeitner::__private::BlockSummary {
                        name: "b",
                        rows: 4,
                        cols: 1,
                        nonzeros: &[(0, 0), (1, 0), (2, 0), (3, 0)],
                    },
                ],
                ops: ::zeitner::__private::OpCounts {
                    adds: 4u64,
                    muls: 9u64,
                    divs: 1u64,
                    transcendental: 2u64,
                    opaque_calls: 0u64,
                },
                ops_unshared: ::zeitner::__private::OpCounts {
                    adds: 5u64,
                    muls: 19u64,
                    divs: 1u64,
                    transcendental: 8u64,
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
                        nonzeros: &[(2, 2)],
                    },
                    ::zeitner::__private::BlockSummary {
                        name: "dv",
                        rows: 3,
                        cols: 3,
                        nonzeros: &[],
                    },
                ],
                ops: ::zeitner::__private::OpCounts {
                    adds: 3u64,
                    muls: 6u64,
                    divs: 0u64,
                    transcendental: 2u64,
                    opaque_calls: 0u64,
                },
                ops_unshared: ::zeitner::__private::OpCounts {
                    adds: 3u64,
                    muls: 8u64,
                    divs: 0u64,
                    transcendental: 4u64,
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
        ],
    };
    type Mass = ::zeitner::__private::DiagonalMass<3>;
    type Storage = ::zeitner::__private::Dense;
    const UNILATERAL_CONSTRAINTS: usize = 2usize;
    const SLIDING_CONTACTS: usize = 2usize;
    const SPARSITY: ::core::option::Option<::zeitner::__private::Sparsity> = ::core::option::Option::Some(::zeitner::__private::Sparsity {
        constraint_jacobian: &[
            (0, 1),
            (0, 2),
            (1, 1),
            (1, 2),
            (2, 0),
            (2, 2),
            (3, 0),
            (3, 2),
        ],
        force_jacobians: [&[], &[]],
        constraint_force_jacobians: [&[(2, 2)], &[]],
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
        m[2] = self.l * (self.m * self.l) / 3.0;
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
        f[1] = -(self.m * self.g);
        f
    }
    #[inline]
    fn constraint_residual(
        &self,
        q: &::zeitner::__private::Vector<3>,
        v: &::zeitner::__private::Vector<3>,
        t: ::zeitner::__private::Float,
    ) -> ::zeitner::__private::Vector<4> {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let s0 = self.l * q[2].sin();
        let s1 = s0 * v[2];
        let mut g = ::zeitner::__private::Vector::<4>::zeros();
        g[0] = self.ceiling - q[1] - s0;
        g[1] = q[1] - s0;
        g[2] = v[0] - s1;
        g[3] = v[0] + s1;
        g
    }
    #[inline]
    fn constraint_jacobian(
        &self,
        q: &::zeitner::__private::Vector<3>,
        v: &::zeitner::__private::Vector<3>,
        t: ::zeitner::__private::Float,
    ) -> ::zeitner::__private::Matrix<4, 3> {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let s0 = self.l * q[2].sin();
        let s1 = -(self.l * q[2].cos());
        let mut g = ::zeitner::__private::Matrix::<4, 3>::zeros();
        g[(0, 1)] = -1.0;
        g[(0, 2)] = s1;
        g[(1, 1)] = 1.0;
        g[(1, 2)] = s1;
        g[(2, 0)] = 1.0;
        g[(2, 2)] = -s0;
        g[(3, 0)] = 1.0;
        g[(3, 2)] = s0;
        g
    }
    #[inline]
    fn constraint_position_partials(
        &self,
        q: &::zeitner::__private::Vector<3>,
        v: &::zeitner::__private::Vector<3>,
        t: ::zeitner::__private::Float,
    ) -> ::zeitner::__private::Matrix<4, 3> {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let s0 = self.l * q[2].cos();
        let s1 = -s0;
        let s2 = v[2] * s0;
        let mut p = ::zeitner::__private::Matrix::<4, 3>::zeros();
        p[(0, 1)] = -1.0;
        p[(0, 2)] = s1;
        p[(1, 1)] = 1.0;
        p[(1, 2)] = s1;
        p[(2, 2)] = -s2;
        p[(3, 2)] = s2;
        p
    }
    #[inline]
    fn constraint_rate(
        &self,
        q: &::zeitner::__private::Vector<3>,
        v: &::zeitner::__private::Vector<3>,
        t: ::zeitner::__private::Float,
    ) -> ::zeitner::__private::Vector<4> {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let s0 = self.l * q[2].sin() * v[2];
        let s1 = v[2] * (self.l * q[2].cos());
        let mut w = ::zeitner::__private::Vector::<4>::zeros();
        w[0] = -v[1] - s1;
        w[1] = v[1] - s1;
        w[2] = v[0] - s0;
        w[3] = v[0] + s0;
        w
    }
    #[inline]
    fn constraint_acceleration_bias(
        &self,
        q: &::zeitner::__private::Vector<3>,
        v: &::zeitner::__private::Vector<3>,
        t: ::zeitner::__private::Float,
    ) -> ::zeitner::__private::Vector<4> {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let s0 = v[2] * (self.l * q[2].sin() * v[2]);
        let s1 = v[2] * (v[2] * (self.l * q[2].cos()));
        let mut b = ::zeitner::__private::Vector::<4>::zeros();
        b[0] = s0;
        b[1] = s0;
        b[2] = -s1;
        b[3] = s1;
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
        ::zeitner::__private::Matrix<4, 3>,
        ::zeitner::__private::Vector<4>,
    ) {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let s0 = self.l * q[2].sin();
        let s1 = self.l * q[2].cos();
        let s2 = -s1;
        let s3 = v[2] * (s0 * v[2]);
        let s4 = v[2] * (v[2] * s1);
        let mut m = ::zeitner::__private::Vector::<3>::zeros();
        let mut f = ::zeitner::__private::Vector::<3>::zeros();
        let mut g = ::zeitner::__private::Matrix::<4, 3>::zeros();
        let mut b = ::zeitner::__private::Vector::<4>::zeros();
        m[0] = self.m;
        m[1] = self.m;
        m[2] = self.l * (self.m * self.l) / 3.0;
        f[1] = -(self.m * self.g);
        g[(0, 1)] = -1.0;
        g[(0, 2)] = s2;
        g[(1, 1)] = 1.0;
        g[(1, 2)] = s2;
        g[(2, 0)] = 1.0;
        g[(2, 2)] = -s0;
        g[(3, 0)] = 1.0;
        g[(3, 2)] = s0;
        b[0] = s3;
        b[1] = s3;
        b[2] = -s4;
        b[3] = s4;
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
        lambda: &::zeitner::__private::Vector<4>,
    ) -> (::zeitner::__private::Matrix<3, 3>, ::zeitner::__private::Matrix<3, 3>) {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let s0 = self.l * q[2].sin();
        let s1 = self.l * q[2].cos();
        let mut dq = ::zeitner::__private::Matrix::<3, 3>::zeros();
        let mut dv = ::zeitner::__private::Matrix::<3, 3>::zeros();
        dq[(2, 2)] = s0 * lambda[0] + s0 * lambda[1] - s1 * lambda[2] + s1 * lambda[3];
        (dq, dv)
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
    fn constraint_jacobian_nonzeros(
        &self,
        q: &::zeitner::__private::Vector<3>,
        v: &::zeitner::__private::Vector<3>,
        t: ::zeitner::__private::Float,
        values: &mut [::zeitner::__private::Float],
    ) {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let s0 = self.l * q[2].sin();
        let s1 = -(self.l * q[2].cos());
        values[0] = -1.0;
        values[1] = s1;
        values[2] = 1.0;
        values[3] = s1;
        values[4] = 1.0;
        values[5] = -s0;
        values[6] = 1.0;
        values[7] = s0;
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
        lambda: &::zeitner::__private::Vector<4>,
        values: &mut [::zeitner::__private::Float],
    ) {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let s0 = self.l * q[2].sin();
        let s1 = self.l * q[2].cos();
        values[0] = s0 * lambda[0] + s0 * lambda[1] - s1 * lambda[2] + s1 * lambda[3];
    }
}
#[allow(dead_code)]
impl Disk {
    fn mass(&self) -> [Float; 3] {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        [self.m, self.m, 0.5 * self.m * self.r * self.r]
    }
    fn force(&self) -> [Float; 3] {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        [0.0, -self.m * self.g, 0.0]
    }
    fn gaps(&self, [_x, y, _phi]: [Float; 3]) -> [Float; 1] {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        [y - self.r]
    }
    /// The velocity of the disk's lowest point along the floor.
    fn slips(&self, _q: [Float; 3], [vx, _vy, w]: [Float; 3]) -> [Float; 1] {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        [vx + self.r * w]
    }
    fn restitution(&self) -> [Float; 1] {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        [self.e]
    }
    fn friction(&self) -> [Float; 1] {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        [self.mu]
    }
}
#[allow(unused_variables, unused_mut, clippy::all)]
impl ::zeitner::__private::ConstrainedSystem<3, 2> for Disk {
    const POSITION_CONSTRAINTS: usize = 1;
    const MASS_IS_CONSTANT: bool = true;
    const DYNAMICS_DEPEND_ON_VELOCITY: bool = false;
    const SUMMARY: ::zeitner::__private::SceneSummary = ::zeitner::__private::SceneSummary {
        coordinates: 3,
        position_constraints: 1,
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
                    muls: 3u64,
                    divs: 0u64,
                    transcendental: 0u64,
                    opaque_calls: 0u64,
                },
                ops_unshared: ::zeitner::__private::OpCounts {
                    adds: 0u64,
                    muls: 3u64,
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
                        nonzeros: &[(1, 0)],
                    },
                ],
                ops: ::zeitner::__private::OpCounts {
                    adds: 1u64,
                    muls: 1u64,
                    divs: 0u64,
                    transcendental: 0u64,
                    opaque_calls: 0u64,
                },
                ops_unshared: ::zeitner::__private::OpCounts {
                    adds: 1u64,
                    muls: 1u64,
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
                        rows: 2,
                        cols: 1,
                        nonzeros: &[(0, 0), (1, 0)],
                    },
                ],
                ops: ::zeitner::__private::OpCounts {
                    adds: 2u64,
                    muls: 1u64,
                    divs: 0u64,
                    transcendental: 0u64,
                    opaque_calls: 0u64,
                },
                ops_unshared: ::zeitner::__private::OpCounts {
                    adds: 2u64,
                    muls: 1u64,
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
                        nonzeros: &[(0, 1), (1, 0), (1, 2)],
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
                name: "constraint_position_partials",
                blocks: &[
                    ::zeitner::__private::BlockSummary {
                        name: "p",
                        rows: 2,
                        cols: 3,
                        nonzeros: &[(0, 1)],
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
                    adds: 1u64,
                    muls: 1u64,
                    divs: 0u64,
                    transcendental: 0u64,
                    opaque_calls: 0u64,
                },
                ops_unshared: ::zeitner::__private::OpCounts {
                    adds: 1u64,
                    muls: 1u64,
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
                        nonzeros: &[(1, 0)],
                    },
                    ::zeitner::__private::BlockSummary {
                        name: "g",
                        rows: 2,
                        cols: 3,
                        nonzeros: &[(0, 1), (1, 0), (1, 2)],
                    },
                    ::zeitner::__private::BlockSummary {
                        name: "b",
                        rows: 2,
                        cols: 1,
                        nonzeros: &[],
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
                name: "restitution",
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
            ::zeitner::__private::FunctionSummary {
                name: "friction",
                blocks: &[
                    ::zeitner::__private::BlockSummary {
                        name: "mu",
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
    type Mass = ::zeitner::__private::DiagonalMass<3>;
    type Storage = ::zeitner::__private::Dense;
    const UNILATERAL_CONSTRAINTS: usize = 1usize;
    const SLIDING_CONTACTS: usize = 1usize;
    const SPARSITY: ::core::option::Option<::zeitner::__private::Sparsity> = ::core::option::Option::Some(::zeitner::__private::Sparsity {
        constraint_jacobian: &[(0, 1), (1, 0), (1, 2)],
        force_jacobians: [&[], &[]],
        constraint_force_jacobians: [&[], &[]],
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
        m[2] = self.r * (0.5 * self.m * self.r);
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
        f[1] = -(self.m * self.g);
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
        g[0] = q[1] - self.r;
        g[1] = v[0] + self.r * v[2];
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
        g[(0, 1)] = 1.0;
        g[(1, 0)] = 1.0;
        g[(1, 2)] = self.r;
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
        p[(0, 1)] = 1.0;
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
        w[0] = v[1];
        w[1] = v[0] + self.r * v[2];
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
        let mut m = ::zeitner::__private::Vector::<3>::zeros();
        let mut f = ::zeitner::__private::Vector::<3>::zeros();
        let mut g = ::zeitner::__private::Matrix::<2, 3>::zeros();
        let mut b = ::zeitner::__private::Vector::<2>::zeros();
        m[0] = self.m;
        m[1] = self.m;
        m[2] = self.r * (0.5 * self.m * self.r);
        f[1] = -(self.m * self.g);
        g[(0, 1)] = 1.0;
        g[(1, 0)] = 1.0;
        g[(1, 2)] = self.r;
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
        (dq, dv)
    }
    #[inline]
    fn restitution(&self, gap: usize) -> ::zeitner::__private::Float {
        let e = {
            #[allow(unused_imports)]
            use ::zeitner::__private::Real as _;
            let mut e = ::zeitner::__private::Vector::<1>::zeros();
            e[0] = self.e;
            e
        };
        if gap < 1 { e[gap] } else { 0.0 }
    }
    #[inline]
    fn friction(&self, gap: usize) -> ::zeitner::__private::Float {
        let mu = {
            #[allow(unused_imports)]
            use ::zeitner::__private::Real as _;
            let mut mu = ::zeitner::__private::Vector::<1>::zeros();
            mu[0] = self.mu;
            mu
        };
        if gap < 1 { mu[gap] } else { 0.0 }
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
        values[1] = 1.0;
        values[2] = self.r;
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
    }
}
#[allow(dead_code)]
impl TwoBlocks {
    fn mass(&self) -> [Float; 4] {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        [self.m, self.m, self.m, self.m]
    }
    fn force(&self, [x1, _y1, x2, _y2]: [Float; 4]) -> [Float; 4] {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let pull = self.k * (x2 - x1 - self.rest);
        [pull, -self.m * self.g, -pull, -self.m * self.g]
    }
    fn gaps(&self, [_x1, y1, _x2, y2]: [Float; 4]) -> [Float; 2] {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        [y1, y2]
    }
    fn slips(&self, _q: [Float; 4], [vx1, _vy1, vx2, _vy2]: [Float; 4]) -> [Float; 2] {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        [vx1, vx2]
    }
    fn friction(&self) -> [Float; 2] {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        [self.mu, self.mu]
    }
}
#[allow(unused_variables, unused_mut, clippy::all)]
impl ::zeitner::__private::ConstrainedSystem<4, 4> for TwoBlocks {
    const POSITION_CONSTRAINTS: usize = 2;
    const MASS_IS_CONSTANT: bool = true;
    const DYNAMICS_DEPEND_ON_VELOCITY: bool = false;
    const SUMMARY: ::zeitner::__private::SceneSummary = ::zeitner::__private::SceneSummary {
        coordinates: 4,
        position_constraints: 2,
        velocity_constraints: 2,
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
                        nonzeros: &[(0, 0), (1, 0), (2, 0), (3, 0)],
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
                    adds: 7u64,
                    muls: 4u64,
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
                name: "constraint_jacobian",
                blocks: &[
                    ::zeitner::__private::BlockSummary {
                        name: "g",
                        rows: 4,
                        cols: 4,
                        nonzeros: &[(0, 1), (1, 3), (2, 0), (3, 2)],
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
                name: "constraint_position_partials",
                blocks: &[
                    ::zeitner::__private::BlockSummary {
                        name: "p",
                        rows: 4,
                        cols: 4,
                        nonzeros: &[(0, 1), (1, 3)],
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
                name: "constraint_rate",
                blocks: &[
                    ::zeitner::__private::BlockSummary {
                        name: "w",
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
                name: "constraint_acceleration_bias",
                blocks: &[
                    ::zeitner::__private::BlockSummary {
                        name: "b",
                        rows: 4,
                        cols: 1,
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
                        nonzeros: &[(0, 0), (1, 0), (2, 0), (3, 0)],
                    },
                    ::zeitner::__private::BlockSummary {
                        name: "g",
                        rows: 4,
                        cols: 4,
                        nonzeros: &[(0, 1), (1, 3), (2, 0), (3, 2)],
                    },
                    ::zeitner::__private::BlockSummary {
                        name: "b",
                        rows: 4,
                        cols: 1,
                        nonzeros: &[],
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
                    adds: 7u64,
                    muls: 4u64,
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
                        nonzeros: &[(0, 0), (0, 2), (2, 0), (2, 2)],
                    },
                    ::zeitner::__private::BlockSummary {
                        name: "dv",
                        rows: 4,
                        cols: 4,
                        nonzeros: &[],
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
                    adds: 2u64,
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
        ],
    };
    type Mass = ::zeitner::__private::DiagonalMass<4>;
    type Storage = ::zeitner::__private::Dense;
    const UNILATERAL_CONSTRAINTS: usize = 2usize;
    const SLIDING_CONTACTS: usize = 2usize;
    const SPARSITY: ::core::option::Option<::zeitner::__private::Sparsity> = ::core::option::Option::Some(::zeitner::__private::Sparsity {
        constraint_jacobian: &[(0, 1), (1, 3), (2, 0), (3, 2)],
        force_jacobians: [&[(0, 0), (0, 2), (2, 0), (2, 2)], &[]],
        constraint_force_jacobians: [&[], &[]],
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
        let s0 = self.k * (q[2] - q[0] - self.rest);
        let s1 = -(self.m * self.g);
        let mut f = ::zeitner::__private::Vector::<4>::zeros();
        f[0] = s0;
        f[1] = s1;
        f[2] = -s0;
        f[3] = s1;
        f
    }
    #[inline]
    fn constraint_residual(
        &self,
        q: &::zeitner::__private::Vector<4>,
        v: &::zeitner::__private::Vector<4>,
        t: ::zeitner::__private::Float,
    ) -> ::zeitner::__private::Vector<4> {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let mut g = ::zeitner::__private::Vector::<4>::zeros();
        g[0] = q[1];
        g[1] = q[3];
        g[2] = v[0];
        g[3] = v[2];
        g
    }
    #[inline]
    fn constraint_jacobian(
        &self,
        q: &::zeitner::__private::Vector<4>,
        v: &::zeitner::__private::Vector<4>,
        t: ::zeitner::__private::Float,
    ) -> ::zeitner::__private::Matrix<4, 4> {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let mut g = ::zeitner::__private::Matrix::<4, 4>::zeros();
        g[(0, 1)] = 1.0;
        g[(1, 3)] = 1.0;
        g[(2, 0)] = 1.0;
        g[(3, 2)] = 1.0;
        g
    }
    #[inline]
    fn constraint_position_partials(
        &self,
        q: &::zeitner::__private::Vector<4>,
        v: &::zeitner::__private::Vector<4>,
        t: ::zeitner::__private::Float,
    ) -> ::zeitner::__private::Matrix<4, 4> {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let mut p = ::zeitner::__private::Matrix::<4, 4>::zeros();
        p[(0, 1)] = 1.0;
        p[(1, 3)] = 1.0;
        p
    }
    #[inline]
    fn constraint_rate(
        &self,
        q: &::zeitner::__private::Vector<4>,
        v: &::zeitner::__private::Vector<4>,
        t: ::zeitner::__private::Float,
    ) -> ::zeitner::__private::Vector<4> {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let mut w = ::zeitner::__private::Vector::<4>::zeros();
        w[0] = v[1];
        w[1] = v[3];
        w[2] = v[0];
        w[3] = v[2];
        w
    }
    #[inline]
    fn constraint_acceleration_bias(
        &self,
        q: &::zeitner::__private::Vector<4>,
        v: &::zeitner::__private::Vector<4>,
        t: ::zeitner::__private::Float,
    ) -> ::zeitner::__private::Vector<4> {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let mut b = ::zeitner::__private::Vector::<4>::zeros();
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
        ::zeitner::__private::Matrix<4, 4>,
        ::zeitner::__private::Vector<4>,
    ) {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let s0 = self.k * (q[2] - q[0] - self.rest);
        let s1 = -(self.m * self.g);
        let mut m = ::zeitner::__private::Vector::<4>::zeros();
        let mut f = ::zeitner::__private::Vector::<4>::zeros();
        let mut g = ::zeitner::__private::Matrix::<4, 4>::zeros();
        let mut b = ::zeitner::__private::Vector::<4>::zeros();
        m[0] = self.m;
        m[1] = self.m;
        m[2] = self.m;
        m[3] = self.m;
        f[0] = s0;
        f[1] = s1;
        f[2] = -s0;
        f[3] = s1;
        g[(0, 1)] = 1.0;
        g[(1, 3)] = 1.0;
        g[(2, 0)] = 1.0;
        g[(3, 2)] = 1.0;
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
        let mut dq = ::zeitner::__private::Matrix::<4, 4>::zeros();
        let mut dv = ::zeitner::__private::Matrix::<4, 4>::zeros();
        dq[(0, 0)] = s0;
        dq[(0, 2)] = self.k;
        dq[(2, 0)] = self.k;
        dq[(2, 2)] = s0;
        (dq, dv)
    }
    #[inline]
    fn constraint_force_jacobians(
        &self,
        q: &::zeitner::__private::Vector<4>,
        v: &::zeitner::__private::Vector<4>,
        t: ::zeitner::__private::Float,
        lambda: &::zeitner::__private::Vector<4>,
    ) -> (::zeitner::__private::Matrix<4, 4>, ::zeitner::__private::Matrix<4, 4>) {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let mut dq = ::zeitner::__private::Matrix::<4, 4>::zeros();
        let mut dv = ::zeitner::__private::Matrix::<4, 4>::zeros();
        (dq, dv)
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
    fn constraint_jacobian_nonzeros(
        &self,
        q: &::zeitner::__private::Vector<4>,
        v: &::zeitner::__private::Vector<4>,
        t: ::zeitner::__private::Float,
        values: &mut [::zeitner::__private::Float],
    ) {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        values[0] = 1.0;
        values[1] = 1.0;
        values[2] = 1.0;
        values[3] = 1.0;
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
        values[0] = s0;
        values[1] = self.k;
        values[2] = self.k;
        values[3] = s0;
    }
    #[inline]
    fn constraint_force_jacobian_nonzeros(
        &self,
        q: &::zeitner::__private::Vector<4>,
        v: &::zeitner::__private::Vector<4>,
        t: ::zeitner::__private::Float,
        lambda: &::zeitner::__private::Vector<4>,
        values: &mut [::zeitner::__private::Float],
    ) {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
    }
}
#[allow(dead_code)]
impl Ball {
    fn mass(&self) -> [Float; 6] {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let inertia = 0.4 * self.m * self.r * self.r;
        [self.m, self.m, self.m, inertia, inertia, inertia]
    }
    fn force(&self) -> [Float; 6] {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        [0.0, 0.0, -self.m * self.g, 0.0, 0.0, 0.0]
    }
    fn gaps(&self, [_x, _y, z, _ax, _ay, _az]: [Float; 6]) -> [Float; 1] {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        [z - self.r]
    }
    fn slips(
        &self,
        _q: [Float; 6],
        [vx,
        vy,
        _vz,
        wx,
        wy,
        _wz,
        ]: [Float; 6],
    ) -> [Float; 2] {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        [vx - self.r * wy, vy + self.r * wx]
    }
    fn friction(&self) -> [Float; 1] {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        [self.mu]
    }
    fn restitution(&self) -> [Float; 1] {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        [self.e]
    }
}
#[allow(unused_variables, unused_mut, clippy::all)]
impl ::zeitner::__private::ConstrainedSystem<6, 3> for Ball {
    const POSITION_CONSTRAINTS: usize = 1;
    const MASS_IS_CONSTANT: bool = true;
    const DYNAMICS_DEPEND_ON_VELOCITY: bool = true;
    const SUMMARY: ::zeitner::__private::SceneSummary = ::zeitner::__private::SceneSummary {
        coordinates: 6,
        position_constraints: 1,
        velocity_constraints: 2,
        mass: ::zeitner::__private::MassKind::ConstantDiagonal,
        time_dependent: false,
        functions: &[
            ::zeitner::__private::FunctionSummary {
                name: "mass_matrix",
                blocks: &[
                    ::zeitner::__private::BlockSummary {
                        name: "m",
                        rows: 6,
                        cols: 1,
                        nonzeros: &[(0, 0), (1, 0), (2, 0), (3, 0), (4, 0), (5, 0)],
                    },
                ],
                ops: ::zeitner::__private::OpCounts {
                    adds: 0u64,
                    muls: 3u64,
                    divs: 0u64,
                    transcendental: 0u64,
                    opaque_calls: 0u64,
                },
                ops_unshared: ::zeitner::__private::OpCounts {
                    adds: 0u64,
                    muls: 9u64,
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
                        rows: 6,
                        cols: 1,
                        nonzeros: &[(2, 0)],
                    },
                ],
                ops: ::zeitner::__private::OpCounts {
                    adds: 1u64,
                    muls: 1u64,
                    divs: 0u64,
                    transcendental: 0u64,
                    opaque_calls: 0u64,
                },
                ops_unshared: ::zeitner::__private::OpCounts {
                    adds: 1u64,
                    muls: 1u64,
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
                    adds: 3u64,
                    muls: 2u64,
                    divs: 0u64,
                    transcendental: 0u64,
                    opaque_calls: 0u64,
                },
                ops_unshared: ::zeitner::__private::OpCounts {
                    adds: 3u64,
                    muls: 2u64,
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
                        cols: 6,
                        nonzeros: &[(0, 2), (1, 0), (1, 4), (2, 1), (2, 3)],
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
                name: "constraint_position_partials",
                blocks: &[
                    ::zeitner::__private::BlockSummary {
                        name: "p",
                        rows: 3,
                        cols: 6,
                        nonzeros: &[(0, 2)],
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
                name: "constraint_acceleration_bias",
                blocks: &[
                    ::zeitner::__private::BlockSummary {
                        name: "b",
                        rows: 3,
                        cols: 1,
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
                name: "stage",
                blocks: &[
                    ::zeitner::__private::BlockSummary {
                        name: "m",
                        rows: 6,
                        cols: 1,
                        nonzeros: &[(0, 0), (1, 0), (2, 0), (3, 0), (4, 0), (5, 0)],
                    },
                    ::zeitner::__private::BlockSummary {
                        name: "f",
                        rows: 6,
                        cols: 1,
                        nonzeros: &[(2, 0)],
                    },
                    ::zeitner::__private::BlockSummary {
                        name: "g",
                        rows: 3,
                        cols: 6,
                        nonzeros: &[(0, 2), (1, 0), (1, 4), (2, 1), (2, 3)],
                    },
                    ::zeitner::__private::BlockSummary {
                        name: "b",
                        rows: 3,
                        cols: 1,
                        nonzeros: &[],
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
                    muls: 10u64,
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
                        rows: 6,
                        cols: 6,
                        nonzeros: &[],
                    },
                    ::zeitner::__private::BlockSummary {
                        name: "dv",
                        rows: 6,
                        cols: 6,
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
                        rows: 6,
                        cols: 6,
                        nonzeros: &[],
                    },
                    ::zeitner::__private::BlockSummary {
                        name: "dv",
                        rows: 6,
                        cols: 6,
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
                name: "restitution",
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
            ::zeitner::__private::FunctionSummary {
                name: "friction",
                blocks: &[
                    ::zeitner::__private::BlockSummary {
                        name: "mu",
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
    type Mass = ::zeitner::__private::DiagonalMass<6>;
    type Storage = ::zeitner::__private::Dense;
    const UNILATERAL_CONSTRAINTS: usize = 1usize;
    const SLIDING_CONTACTS: usize = 1usize;
    const TANGENTS: usize = 2;
    const SPARSITY: ::core::option::Option<::zeitner::__private::Sparsity> = ::core::option::Option::Some(::zeitner::__private::Sparsity {
        constraint_jacobian: &[(0, 2), (1, 0), (1, 4), (2, 1), (2, 3)],
        force_jacobians: [&[], &[]],
        constraint_force_jacobians: [&[], &[]],
    });
    #[inline]
    fn mass_matrix(
        &self,
        q: &::zeitner::__private::Vector<6>,
        t: ::zeitner::__private::Float,
    ) -> Self::Mass {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let s0 = self.r * (0.4 * self.m * self.r);
        let mut m = ::zeitner::__private::Vector::<6>::zeros();
        m[0] = self.m;
        m[1] = self.m;
        m[2] = self.m;
        m[3] = s0;
        m[4] = s0;
        m[5] = s0;
        ::zeitner::__private::DiagonalMass(m)
    }
    #[inline]
    fn applied_force(
        &self,
        q: &::zeitner::__private::Vector<6>,
        v: &::zeitner::__private::Vector<6>,
        t: ::zeitner::__private::Float,
    ) -> ::zeitner::__private::Vector<6> {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let mut f = ::zeitner::__private::Vector::<6>::zeros();
        f[2] = -(self.m * self.g);
        f
    }
    #[inline]
    fn constraint_residual(
        &self,
        q: &::zeitner::__private::Vector<6>,
        v: &::zeitner::__private::Vector<6>,
        t: ::zeitner::__private::Float,
    ) -> ::zeitner::__private::Vector<3> {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let mut g = ::zeitner::__private::Vector::<3>::zeros();
        g[0] = q[2] - self.r;
        g[1] = v[0] - self.r * v[4];
        g[2] = v[1] + self.r * v[3];
        g
    }
    #[inline]
    fn constraint_jacobian(
        &self,
        q: &::zeitner::__private::Vector<6>,
        v: &::zeitner::__private::Vector<6>,
        t: ::zeitner::__private::Float,
    ) -> ::zeitner::__private::Matrix<3, 6> {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let mut g = ::zeitner::__private::Matrix::<3, 6>::zeros();
        g[(0, 2)] = 1.0;
        g[(1, 0)] = 1.0;
        g[(1, 4)] = -self.r;
        g[(2, 1)] = 1.0;
        g[(2, 3)] = self.r;
        g
    }
    #[inline]
    fn constraint_position_partials(
        &self,
        q: &::zeitner::__private::Vector<6>,
        v: &::zeitner::__private::Vector<6>,
        t: ::zeitner::__private::Float,
    ) -> ::zeitner::__private::Matrix<3, 6> {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let mut p = ::zeitner::__private::Matrix::<3, 6>::zeros();
        p[(0, 2)] = 1.0;
        p
    }
    #[inline]
    fn constraint_rate(
        &self,
        q: &::zeitner::__private::Vector<6>,
        v: &::zeitner::__private::Vector<6>,
        t: ::zeitner::__private::Float,
    ) -> ::zeitner::__private::Vector<3> {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let mut w = ::zeitner::__private::Vector::<3>::zeros();
        w[0] = v[2];
        w[1] = v[0] - self.r * v[4];
        w[2] = v[1] + self.r * v[3];
        w
    }
    #[inline]
    fn constraint_acceleration_bias(
        &self,
        q: &::zeitner::__private::Vector<6>,
        v: &::zeitner::__private::Vector<6>,
        t: ::zeitner::__private::Float,
    ) -> ::zeitner::__private::Vector<3> {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let mut b = ::zeitner::__private::Vector::<3>::zeros();
        b
    }
    #[inline]
    fn stage(
        &self,
        q: &::zeitner::__private::Vector<6>,
        v: &::zeitner::__private::Vector<6>,
        t: ::zeitner::__private::Float,
    ) -> (
        Self::Mass,
        ::zeitner::__private::Vector<6>,
        ::zeitner::__private::Matrix<3, 6>,
        ::zeitner::__private::Vector<3>,
    ) {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let s0 = self.r * (0.4 * self.m * self.r);
        let mut m = ::zeitner::__private::Vector::<6>::zeros();
        let mut f = ::zeitner::__private::Vector::<6>::zeros();
        let mut g = ::zeitner::__private::Matrix::<3, 6>::zeros();
        let mut b = ::zeitner::__private::Vector::<3>::zeros();
        m[0] = self.m;
        m[1] = self.m;
        m[2] = self.m;
        m[3] = s0;
        m[4] = s0;
        m[5] = s0;
        f[2] = -(self.m * self.g);
        g[(0, 2)] = 1.0;
        g[(1, 0)] = 1.0;
        g[(1, 4)] = -self.r;
        g[(2, 1)] = 1.0;
        g[(2, 3)] = self.r;
        (::zeitner::__private::DiagonalMass(m), f, g, b)
    }
    #[inline]
    fn force_jacobians(
        &self,
        q: &::zeitner::__private::Vector<6>,
        v: &::zeitner::__private::Vector<6>,
        t: ::zeitner::__private::Float,
    ) -> (::zeitner::__private::Matrix<6, 6>, ::zeitner::__private::Matrix<6, 6>) {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let mut dq = ::zeitner::__private::Matrix::<6, 6>::zeros();
        let mut dv = ::zeitner::__private::Matrix::<6, 6>::zeros();
        (dq, dv)
    }
    #[inline]
    fn constraint_force_jacobians(
        &self,
        q: &::zeitner::__private::Vector<6>,
        v: &::zeitner::__private::Vector<6>,
        t: ::zeitner::__private::Float,
        lambda: &::zeitner::__private::Vector<3>,
    ) -> (::zeitner::__private::Matrix<6, 6>, ::zeitner::__private::Matrix<6, 6>) {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let mut dq = ::zeitner::__private::Matrix::<6, 6>::zeros();
        let mut dv = ::zeitner::__private::Matrix::<6, 6>::zeros();
        (dq, dv)
    }
    #[inline]
    fn restitution(&self, gap: usize) -> ::zeitner::__private::Float {
        let e = {
            #[allow(unused_imports)]
            use ::zeitner::__private::Real as _;
            let mut e = ::zeitner::__private::Vector::<1>::zeros();
            e[0] = self.e;
            e
        };
        if gap < 1 { e[gap] } else { 0.0 }
    }
    #[inline]
    fn friction(&self, gap: usize) -> ::zeitner::__private::Float {
        let mu = {
            #[allow(unused_imports)]
            use ::zeitner::__private::Real as _;
            let mut mu = ::zeitner::__private::Vector::<1>::zeros();
            mu[0] = self.mu;
            mu
        };
        if gap < 1 { mu[gap] } else { 0.0 }
    }
    #[inline]
    fn constraint_jacobian_nonzeros(
        &self,
        q: &::zeitner::__private::Vector<6>,
        v: &::zeitner::__private::Vector<6>,
        t: ::zeitner::__private::Float,
        values: &mut [::zeitner::__private::Float],
    ) {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        values[0] = 1.0;
        values[1] = 1.0;
        values[2] = -self.r;
        values[3] = 1.0;
        values[4] = self.r;
    }
    #[inline]
    fn force_jacobian_nonzeros(
        &self,
        q: &::zeitner::__private::Vector<6>,
        v: &::zeitner::__private::Vector<6>,
        t: ::zeitner::__private::Float,
        values: &mut [::zeitner::__private::Float],
    ) {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
    }
    #[inline]
    fn constraint_force_jacobian_nonzeros(
        &self,
        q: &::zeitner::__private::Vector<6>,
        v: &::zeitner::__private::Vector<6>,
        t: ::zeitner::__private::Float,
        lambda: &::zeitner::__private::Vector<3>,
        values: &mut [::zeitner::__private::Float],
    ) {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
    }
}
#[allow(dead_code)]
impl SlopeAcross {
    fn mass(&self) -> [Float; 3] {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        [self.m, self.m, self.m]
    }
    fn force(&self) -> [Float; 3] {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        [0.0, 0.0, -self.m * self.g]
    }
    fn gaps(&self, [_x, y, z]: [Float; 3]) -> [Float; 1] {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        [z * self.angle.cos() - y * self.angle.sin()]
    }
    fn slips(&self, _q: [Float; 3], [vx, vy, vz]: [Float; 3]) -> [Float; 2] {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        [vx, vy * self.angle.cos() + vz * self.angle.sin()]
    }
    fn friction(&self) -> [Float; 1] {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        [self.mu]
    }
}
#[allow(unused_variables, unused_mut, clippy::all)]
impl ::zeitner::__private::ConstrainedSystem<3, 3> for SlopeAcross {
    const POSITION_CONSTRAINTS: usize = 1;
    const MASS_IS_CONSTANT: bool = true;
    const DYNAMICS_DEPEND_ON_VELOCITY: bool = true;
    const SUMMARY: ::zeitner::__private::SceneSummary = ::zeitner::__private::SceneSummary {
        coordinates: 3,
        position_constraints: 1,
        velocity_constraints: 2,
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
                        nonzeros: &[(2, 0)],
                    },
                ],
                ops: ::zeitner::__private::OpCounts {
                    adds: 1u64,
                    muls: 1u64,
                    divs: 0u64,
                    transcendental: 0u64,
                    opaque_calls: 0u64,
                },
                ops_unshared: ::zeitner::__private::OpCounts {
                    adds: 1u64,
                    muls: 1u64,
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
                    transcendental: 4u64,
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
                        nonzeros: &[(0, 1), (0, 2), (1, 0), (2, 1), (2, 2)],
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
                    transcendental: 4u64,
                    opaque_calls: 0u64,
                },
            },
            ::zeitner::__private::FunctionSummary {
                name: "constraint_position_partials",
                blocks: &[
                    ::zeitner::__private::BlockSummary {
                        name: "p",
                        rows: 3,
                        cols: 3,
                        nonzeros: &[(0, 1), (0, 2)],
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
                    transcendental: 4u64,
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
                        nonzeros: &[(2, 0)],
                    },
                    ::zeitner::__private::BlockSummary {
                        name: "g",
                        rows: 3,
                        cols: 3,
                        nonzeros: &[(0, 1), (0, 2), (1, 0), (2, 1), (2, 2)],
                    },
                    ::zeitner::__private::BlockSummary {
                        name: "b",
                        rows: 3,
                        cols: 1,
                        nonzeros: &[],
                    },
                ],
                ops: ::zeitner::__private::OpCounts {
                    adds: 2u64,
                    muls: 1u64,
                    divs: 0u64,
                    transcendental: 2u64,
                    opaque_calls: 0u64,
                },
                ops_unshared: ::zeitner::__private::OpCounts {
                    adds: 2u64,
                    muls: 1u64,
                    divs: 0u64,
                    transcendental: 4u64,
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
                name: "friction",
                blocks: &[
                    ::zeitner::__private::BlockSummary {
                        name: "mu",
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
    type Mass = ::zeitner::__private::DiagonalMass<3>;
    type Storage = ::zeitner::__private::Dense;
    const UNILATERAL_CONSTRAINTS: usize = 1usize;
    const SLIDING_CONTACTS: usize = 1usize;
    const TANGENTS: usize = 2;
    const SPARSITY: ::core::option::Option<::zeitner::__private::Sparsity> = ::core::option::Option::Some(::zeitner::__private::Sparsity {
        constraint_jacobian: &[(0, 1), (0, 2), (1, 0), (2, 1), (2, 2)],
        force_jacobians: [&[], &[]],
        constraint_force_jacobians: [&[], &[]],
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
        m[2] = self.m;
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
        f[2] = -(self.m * self.g);
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
        let s0 = self.angle.cos();
        let s1 = self.angle.sin();
        let mut g = ::zeitner::__private::Vector::<3>::zeros();
        g[0] = q[2] * s0 - q[1] * s1;
        g[1] = v[0];
        g[2] = s0 * v[1] + s1 * v[2];
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
        let s0 = self.angle.cos();
        let s1 = self.angle.sin();
        let mut g = ::zeitner::__private::Matrix::<3, 3>::zeros();
        g[(0, 1)] = -s1;
        g[(0, 2)] = s0;
        g[(1, 0)] = 1.0;
        g[(2, 1)] = s0;
        g[(2, 2)] = s1;
        g
    }
    #[inline]
    fn constraint_position_partials(
        &self,
        q: &::zeitner::__private::Vector<3>,
        v: &::zeitner::__private::Vector<3>,
        t: ::zeitner::__private::Float,
    ) -> ::zeitner::__private::Matrix<3, 3> {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let mut p = ::zeitner::__private::Matrix::<3, 3>::zeros();
        p[(0, 1)] = -self.angle.sin();
        p[(0, 2)] = self.angle.cos();
        p
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
        let s0 = self.angle.cos();
        let s1 = self.angle.sin();
        let mut w = ::zeitner::__private::Vector::<3>::zeros();
        w[0] = s0 * v[2] - s1 * v[1];
        w[1] = v[0];
        w[2] = s0 * v[1] + s1 * v[2];
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
        let s0 = self.angle.cos();
        let s1 = self.angle.sin();
        let mut m = ::zeitner::__private::Vector::<3>::zeros();
        let mut f = ::zeitner::__private::Vector::<3>::zeros();
        let mut g = ::zeitner::__private::Matrix::<3, 3>::zeros();
        let mut b = ::zeitner::__private::Vector::<3>::zeros();
        m[0] = self.m;
        m[1] = self.m;
        m[2] = self.m;
        f[2] = -(self.m * self.g);
        g[(0, 1)] = -s1;
        g[(0, 2)] = s0;
        g[(1, 0)] = 1.0;
        g[(2, 1)] = s0;
        g[(2, 2)] = s1;
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
        lambda: &::zeitner::__private::Vector<3>,
    ) -> (::zeitner::__private::Matrix<3, 3>, ::zeitner::__private::Matrix<3, 3>) {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let mut dq = ::zeitner::__private::Matrix::<3, 3>::zeros();
        let mut dv = ::zeitner::__private::Matrix::<3, 3>::zeros();
        (dq, dv)
    }
    #[inline]
    fn friction(&self, gap: usize) -> ::zeitner::__private::Float {
        let mu = {
            #[allow(unused_imports)]
            use ::zeitner::__private::Real as _;
            let mut mu = ::zeitner::__private::Vector::<1>::zeros();
            mu[0] = self.mu;
            mu
        };
        if gap < 1 { mu[gap] } else { 0.0 }
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
        let s0 = self.angle.cos();
        let s1 = self.angle.sin();
        values[0] = -s1;
        values[1] = s0;
        values[2] = 1.0;
        values[3] = s0;
        values[4] = s1;
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
        lambda: &::zeitner::__private::Vector<3>,
        values: &mut [::zeitner::__private::Float],
    ) {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
    }
}
#[allow(dead_code)]
impl PulledBlock {
    fn mass(&self) -> [Float; 3] {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        [self.m, self.m, self.m]
    }
    fn force(&self, t: Float) -> [Float; 3] {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let pull = self.rate * t;
        [pull * self.heading.cos(), pull * self.heading.sin(), -self.m * self.g]
    }
    fn gaps(&self, [_x, _y, z]: [Float; 3]) -> [Float; 1] {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        [z]
    }
    fn slips(&self, _q: [Float; 3], [vx, vy, _vz]: [Float; 3]) -> [Float; 2] {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        [vx, vy]
    }
    fn friction(&self) -> [Float; 1] {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        [self.mu]
    }
}
#[allow(unused_variables, unused_mut, clippy::all)]
impl ::zeitner::__private::ConstrainedSystem<3, 3> for PulledBlock {
    const POSITION_CONSTRAINTS: usize = 1;
    const MASS_IS_CONSTANT: bool = true;
    const DYNAMICS_DEPEND_ON_VELOCITY: bool = true;
    const SUMMARY: ::zeitner::__private::SceneSummary = ::zeitner::__private::SceneSummary {
        coordinates: 3,
        position_constraints: 1,
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
                    adds: 1u64,
                    muls: 4u64,
                    divs: 0u64,
                    transcendental: 2u64,
                    opaque_calls: 0u64,
                },
                ops_unshared: ::zeitner::__private::OpCounts {
                    adds: 1u64,
                    muls: 5u64,
                    divs: 0u64,
                    transcendental: 2u64,
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
                name: "constraint_jacobian",
                blocks: &[
                    ::zeitner::__private::BlockSummary {
                        name: "g",
                        rows: 3,
                        cols: 3,
                        nonzeros: &[(0, 2), (1, 0), (2, 1)],
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
                name: "constraint_position_partials",
                blocks: &[
                    ::zeitner::__private::BlockSummary {
                        name: "p",
                        rows: 3,
                        cols: 3,
                        nonzeros: &[(0, 2)],
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
                name: "constraint_acceleration_bias",
                blocks: &[
                    ::zeitner::__private::BlockSummary {
                        name: "b",
                        rows: 3,
                        cols: 1,
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
                        nonzeros: &[(0, 2), (1, 0), (2, 1)],
                    },
                    ::zeitner::__private::BlockSummary {
                        name: "b",
                        rows: 3,
                        cols: 1,
                        nonzeros: &[],
                    },
                ],
                ops: ::zeitner::__private::OpCounts {
                    adds: 1u64,
                    muls: 4u64,
                    divs: 0u64,
                    transcendental: 2u64,
                    opaque_calls: 0u64,
                },
                ops_unshared: ::zeitner::__private::OpCounts {
                    adds: 1u64,
                    muls: 5u64,
                    divs: 0u64,
                    transcendental: 2u64,
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
                name: "friction",
                blocks: &[
                    ::zeitner::__private::BlockSummary {
                        name: "mu",
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
    type Mass = ::zeitner::__private::DiagonalMass<3>;
    type Storage = ::zeitner::__private::Dense;
    const UNILATERAL_CONSTRAINTS: usize = 1usize;
    const SLIDING_CONTACTS: usize = 1usize;
    const TANGENTS: usize = 2;
    const SPARSITY: ::core::option::Option<::zeitner::__private::Sparsity> = ::core::option::Option::Some(::zeitner::__private::Sparsity {
        constraint_jacobian: &[(0, 2), (1, 0), (2, 1)],
        force_jacobians: [&[], &[]],
        constraint_force_jacobians: [&[], &[]],
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
        m[2] = self.m;
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
        let s0 = t * self.rate;
        let mut f = ::zeitner::__private::Vector::<3>::zeros();
        f[0] = s0 * self.heading.cos();
        f[1] = s0 * self.heading.sin();
        f[2] = -(self.m * self.g);
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
        let mut g = ::zeitner::__private::Vector::<3>::zeros();
        g[0] = q[2];
        g[1] = v[0];
        g[2] = v[1];
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
        g[(0, 2)] = 1.0;
        g[(1, 0)] = 1.0;
        g[(2, 1)] = 1.0;
        g
    }
    #[inline]
    fn constraint_position_partials(
        &self,
        q: &::zeitner::__private::Vector<3>,
        v: &::zeitner::__private::Vector<3>,
        t: ::zeitner::__private::Float,
    ) -> ::zeitner::__private::Matrix<3, 3> {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let mut p = ::zeitner::__private::Matrix::<3, 3>::zeros();
        p[(0, 2)] = 1.0;
        p
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
        let mut w = ::zeitner::__private::Vector::<3>::zeros();
        w[0] = v[2];
        w[1] = v[0];
        w[2] = v[1];
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
        let s0 = t * self.rate;
        let mut m = ::zeitner::__private::Vector::<3>::zeros();
        let mut f = ::zeitner::__private::Vector::<3>::zeros();
        let mut g = ::zeitner::__private::Matrix::<3, 3>::zeros();
        let mut b = ::zeitner::__private::Vector::<3>::zeros();
        m[0] = self.m;
        m[1] = self.m;
        m[2] = self.m;
        f[0] = s0 * self.heading.cos();
        f[1] = s0 * self.heading.sin();
        f[2] = -(self.m * self.g);
        g[(0, 2)] = 1.0;
        g[(1, 0)] = 1.0;
        g[(2, 1)] = 1.0;
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
        lambda: &::zeitner::__private::Vector<3>,
    ) -> (::zeitner::__private::Matrix<3, 3>, ::zeitner::__private::Matrix<3, 3>) {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let mut dq = ::zeitner::__private::Matrix::<3, 3>::zeros();
        let mut dv = ::zeitner::__private::Matrix::<3, 3>::zeros();
        (dq, dv)
    }
    #[inline]
    fn friction(&self, gap: usize) -> ::zeitner::__private::Float {
        let mu = {
            #[allow(unused_imports)]
            use ::zeitner::__private::Real as _;
            let mut mu = ::zeitner::__private::Vector::<1>::zeros();
            mu[0] = self.mu;
            mu
        };
        if gap < 1 { mu[gap] } else { 0.0 }
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
        values[1] = 1.0;
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
    }
}
#[allow(dead_code)]
impl Ladder {
    fn mass(&self) -> [Float; 3] {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        [self.m, self.m, self.m * self.l * self.l / 12.0]
    }
    fn force(&self) -> [Float; 3] {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        [0.0, -self.m * self.g, 0.0]
    }
    fn gaps(&self, [x, y, theta]: [Float; 3]) -> [Float; 2] {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let half = 0.5 * self.l;
        [y - half * theta.sin(), x - half * theta.cos()]
    }
    fn slips(&self, [_x, _y, theta]: [Float; 3], [vx, vy, w]: [Float; 3]) -> [Float; 2] {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let half = 0.5 * self.l;
        [vx - half * theta.sin() * w, vy + half * theta.cos() * w]
    }
    fn friction(&self) -> [Float; 2] {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        [self.mu_floor, self.mu_wall]
    }
}
#[allow(unused_variables, unused_mut, clippy::all)]
impl ::zeitner::__private::ConstrainedSystem<3, 4> for Ladder {
    const POSITION_CONSTRAINTS: usize = 2;
    const MASS_IS_CONSTANT: bool = true;
    const DYNAMICS_DEPEND_ON_VELOCITY: bool = false;
    const SUMMARY: ::zeitner::__private::SceneSummary = ::zeitner::__private::SceneSummary {
        coordinates: 3,
        position_constraints: 2,
        velocity_constraints: 2,
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
                    muls: 2u64,
                    divs: 1u64,
                    transcendental: 0u64,
                    opaque_calls: 0u64,
                },
                ops_unshared: ::zeitner::__private::OpCounts {
                    adds: 0u64,
                    muls: 2u64,
                    divs: 1u64,
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
                        nonzeros: &[(1, 0)],
                    },
                ],
                ops: ::zeitner::__private::OpCounts {
                    adds: 1u64,
                    muls: 1u64,
                    divs: 0u64,
                    transcendental: 0u64,
                    opaque_calls: 0u64,
                },
                ops_unshared: ::zeitner::__private::OpCounts {
                    adds: 1u64,
                    muls: 1u64,
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
                        rows: 4,
                        cols: 1,
                        nonzeros: &[(0, 0), (1, 0), (2, 0), (3, 0)],
                    },
                ],
                ops: ::zeitner::__private::OpCounts {
                    adds: 4u64,
                    muls: 5u64,
                    divs: 0u64,
                    transcendental: 2u64,
                    opaque_calls: 0u64,
                },
                ops_unshared: ::zeitner::__private::OpCounts {
                    adds: 4u64,
                    muls: 10u64,
                    divs: 0u64,
                    transcendental: 4u64,
                    opaque_calls: 0u64,
                },
            },
            ::zeitner::__private::FunctionSummary {
                name: "constraint_jacobian",
                blocks: &[
                    ::zeitner::__private::BlockSummary {
                        name: "g",
                        rows: 4,
                        cols: 3,
                        nonzeros: &[
                            (0, 1),
                            (0, 2),
                            (1, 0),
                            (1, 2),
                            (2, 0),
                            (2, 2),
                            (3, 1),
                            (3, 2),
                        ],
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
                    muls: 8u64,
                    divs: 0u64,
                    transcendental: 4u64,
                    opaque_calls: 0u64,
                },
            },
            ::zeitner::__private::FunctionSummary {
                name: "constraint_position_partials",
                blocks: &[
                    ::zeitner::__private::BlockSummary {
                        name: "p",
                        rows: 4,
                        cols: 3,
                        nonzeros: &[(0, 1), (0, 2), (1, 0), (1, 2), (2, 2), (3, 2)],
                    },
                ],
                ops: ::zeitner::__private::OpCounts {
                    adds: 3u64,
                    muls: 5u64,
                    divs: 0u64,
                    transcendental: 2u64,
                    opaque_calls: 0u64,
                },
                ops_unshared: ::zeitner::__private::OpCounts {
                    adds: 3u64,
                    muls: 10u64,
                    divs: 0u64,
                    transcendental: 4u64,
                    opaque_calls: 0u64,
                },
            },
            ::zeitner::__private::FunctionSummary {
                name: "constraint_rate",
                blocks: &[
                    ::zeitner::__private::BlockSummary {
                        name: "w",
                        rows: 4,
                        cols: 1,
                        nonzeros: &[(0, 0), (1, 0), (2, 0), (3, 0)],
                    },
                ],
                ops: ::zeitner::__private::OpCounts {
                    adds: 4u64,
                    muls: 5u64,
                    divs: 0u64,
                    transcendental: 2u64,
                    opaque_calls: 0u64,
                },
                ops_unshared: ::zeitner::__private::OpCounts {
                    adds: 4u64,
                    muls: 12u64,
                    divs: 0u64,
                    transcendental: 4u64,
                    opaque_calls: 0u64,
                },
            },
            ::zeitner::__private::FunctionSummary {
                name: "constraint_acceleration_bias",
                blocks: &[
                    ::zeitner::__private::BlockSummary {
                        name: "b",
                        rows: 4,
                        cols: 1,
                        nonzeros: &[(0, 0), (1, 0), (2, 0), (3, 0)],
                    },
                ],
                ops: ::zeitner::__private::OpCounts {
                    adds: 2u64,
                    muls: 7u64,
                    divs: 0u64,
                    transcendental: 2u64,
                    opaque_calls: 0u64,
                },
                ops_unshared: ::zeitner::__private::OpCounts {
                    adds: 2u64,
                    muls: 16u64,
                    divs: 0u64,
                    transcendental: 4u64,
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
                        nonzeros: &[(1, 0)],
                    },
                    ::zeitner::__private::BlockSummary {
                        name: "g",
                        rows: 4,
                        cols: 3,
                        nonzeros: &[
                            (0, 1),
                            (0, 2),
                            (1, 0),
                            (1, 2),
                            (2, 0),
                            (2, 2),
                            (3, 1),
                            (3, 2),
                        ],
                    },
                    ::zeitner::__private::BlockSummary {
                        name: "b",
                        rows: 4,
                        cols: 1,
                        nonzeros: &[(0, 0), (1, 0), (2, 0), (3, 0)],
                    },
                ],
                ops: ::zeitner::__private::OpCounts {
                    adds: 5u64,
                    muls: 10u64,
                    divs: 1u64,
                    transcendental: 2u64,
                    opaque_calls: 0u64,
                },
                ops_unshared: ::zeitner::__private::OpCounts {
                    adds: 5u64,
                    muls: 27u64,
                    divs: 1u64,
                    transcendental: 8u64,
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
                        nonzeros: &[(2, 2)],
                    },
                    ::zeitner::__private::BlockSummary {
                        name: "dv",
                        rows: 3,
                        cols: 3,
                        nonzeros: &[],
                    },
                ],
                ops: ::zeitner::__private::OpCounts {
                    adds: 3u64,
                    muls: 7u64,
                    divs: 0u64,
                    transcendental: 2u64,
                    opaque_calls: 0u64,
                },
                ops_unshared: ::zeitner::__private::OpCounts {
                    adds: 3u64,
                    muls: 12u64,
                    divs: 0u64,
                    transcendental: 4u64,
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
        ],
    };
    type Mass = ::zeitner::__private::DiagonalMass<3>;
    type Storage = ::zeitner::__private::Dense;
    const UNILATERAL_CONSTRAINTS: usize = 2usize;
    const SLIDING_CONTACTS: usize = 2usize;
    const SPARSITY: ::core::option::Option<::zeitner::__private::Sparsity> = ::core::option::Option::Some(::zeitner::__private::Sparsity {
        constraint_jacobian: &[
            (0, 1),
            (0, 2),
            (1, 0),
            (1, 2),
            (2, 0),
            (2, 2),
            (3, 1),
            (3, 2),
        ],
        force_jacobians: [&[], &[]],
        constraint_force_jacobians: [&[(2, 2)], &[]],
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
        m[2] = self.l * (self.m * self.l) / 12.0;
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
        f[1] = -(self.m * self.g);
        f
    }
    #[inline]
    fn constraint_residual(
        &self,
        q: &::zeitner::__private::Vector<3>,
        v: &::zeitner::__private::Vector<3>,
        t: ::zeitner::__private::Float,
    ) -> ::zeitner::__private::Vector<4> {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let s0 = 0.5 * self.l;
        let s1 = s0 * q[2].sin();
        let s2 = s0 * q[2].cos();
        let mut g = ::zeitner::__private::Vector::<4>::zeros();
        g[0] = q[1] - s1;
        g[1] = q[0] - s2;
        g[2] = v[0] - s1 * v[2];
        g[3] = v[1] + s2 * v[2];
        g
    }
    #[inline]
    fn constraint_jacobian(
        &self,
        q: &::zeitner::__private::Vector<3>,
        v: &::zeitner::__private::Vector<3>,
        t: ::zeitner::__private::Float,
    ) -> ::zeitner::__private::Matrix<4, 3> {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let s0 = 0.5 * self.l;
        let s1 = s0 * q[2].sin();
        let s2 = s0 * q[2].cos();
        let mut g = ::zeitner::__private::Matrix::<4, 3>::zeros();
        g[(0, 1)] = 1.0;
        g[(0, 2)] = -s2;
        g[(1, 0)] = 1.0;
        g[(1, 2)] = s1;
        g[(2, 0)] = 1.0;
        g[(2, 2)] = -s1;
        g[(3, 1)] = 1.0;
        g[(3, 2)] = s2;
        g
    }
    #[inline]
    fn constraint_position_partials(
        &self,
        q: &::zeitner::__private::Vector<3>,
        v: &::zeitner::__private::Vector<3>,
        t: ::zeitner::__private::Float,
    ) -> ::zeitner::__private::Matrix<4, 3> {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let s0 = 0.5 * self.l;
        let s1 = s0 * q[2].sin();
        let s2 = s0 * q[2].cos();
        let mut p = ::zeitner::__private::Matrix::<4, 3>::zeros();
        p[(0, 1)] = 1.0;
        p[(0, 2)] = -s2;
        p[(1, 0)] = 1.0;
        p[(1, 2)] = s1;
        p[(2, 2)] = -(s2 * v[2]);
        p[(3, 2)] = -(s1 * v[2]);
        p
    }
    #[inline]
    fn constraint_rate(
        &self,
        q: &::zeitner::__private::Vector<3>,
        v: &::zeitner::__private::Vector<3>,
        t: ::zeitner::__private::Float,
    ) -> ::zeitner::__private::Vector<4> {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let s0 = 0.5 * self.l;
        let s1 = s0 * q[2].sin() * v[2];
        let s2 = s0 * q[2].cos() * v[2];
        let mut w = ::zeitner::__private::Vector::<4>::zeros();
        w[0] = v[1] - s2;
        w[1] = v[0] + s1;
        w[2] = v[0] - s1;
        w[3] = v[1] + s2;
        w
    }
    #[inline]
    fn constraint_acceleration_bias(
        &self,
        q: &::zeitner::__private::Vector<3>,
        v: &::zeitner::__private::Vector<3>,
        t: ::zeitner::__private::Float,
    ) -> ::zeitner::__private::Vector<4> {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let s0 = 0.5 * self.l;
        let s1 = v[2] * (s0 * q[2].sin() * v[2]);
        let s2 = v[2] * (s0 * q[2].cos() * v[2]);
        let mut b = ::zeitner::__private::Vector::<4>::zeros();
        b[0] = s1;
        b[1] = s2;
        b[2] = -s2;
        b[3] = -s1;
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
        ::zeitner::__private::Matrix<4, 3>,
        ::zeitner::__private::Vector<4>,
    ) {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let s0 = 0.5 * self.l;
        let s1 = s0 * q[2].sin();
        let s2 = s0 * q[2].cos();
        let s3 = v[2] * (s1 * v[2]);
        let s4 = v[2] * (s2 * v[2]);
        let mut m = ::zeitner::__private::Vector::<3>::zeros();
        let mut f = ::zeitner::__private::Vector::<3>::zeros();
        let mut g = ::zeitner::__private::Matrix::<4, 3>::zeros();
        let mut b = ::zeitner::__private::Vector::<4>::zeros();
        m[0] = self.m;
        m[1] = self.m;
        m[2] = self.l * (self.m * self.l) / 12.0;
        f[1] = -(self.m * self.g);
        g[(0, 1)] = 1.0;
        g[(0, 2)] = -s2;
        g[(1, 0)] = 1.0;
        g[(1, 2)] = s1;
        g[(2, 0)] = 1.0;
        g[(2, 2)] = -s1;
        g[(3, 1)] = 1.0;
        g[(3, 2)] = s2;
        b[0] = s3;
        b[1] = s4;
        b[2] = -s4;
        b[3] = -s3;
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
        lambda: &::zeitner::__private::Vector<4>,
    ) -> (::zeitner::__private::Matrix<3, 3>, ::zeitner::__private::Matrix<3, 3>) {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let s0 = 0.5 * self.l;
        let s1 = s0 * q[2].sin();
        let s2 = s0 * q[2].cos();
        let mut dq = ::zeitner::__private::Matrix::<3, 3>::zeros();
        let mut dv = ::zeitner::__private::Matrix::<3, 3>::zeros();
        dq[(2, 2)] = s2 * lambda[1] + s1 * lambda[0] - s2 * lambda[2] - s1 * lambda[3];
        (dq, dv)
    }
    #[inline]
    fn friction(&self, gap: usize) -> ::zeitner::__private::Float {
        let mu = {
            #[allow(unused_imports)]
            use ::zeitner::__private::Real as _;
            let mut mu = ::zeitner::__private::Vector::<2>::zeros();
            mu[0] = self.mu_floor;
            mu[1] = self.mu_wall;
            mu
        };
        if gap < 2 { mu[gap] } else { 0.0 }
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
        let s0 = 0.5 * self.l;
        let s1 = s0 * q[2].sin();
        let s2 = s0 * q[2].cos();
        values[0] = 1.0;
        values[1] = -s2;
        values[2] = 1.0;
        values[3] = s1;
        values[4] = 1.0;
        values[5] = -s1;
        values[6] = 1.0;
        values[7] = s2;
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
        lambda: &::zeitner::__private::Vector<4>,
        values: &mut [::zeitner::__private::Float],
    ) {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let s0 = 0.5 * self.l;
        let s1 = s0 * q[2].sin();
        let s2 = s0 * q[2].cos();
        values[0] = s2 * lambda[1] + s1 * lambda[0] - s2 * lambda[2] - s1 * lambda[3];
    }
}
