#[allow(dead_code)]
impl Chain2 {
    const LINKS: usize = 2;
    fn mass(&self) -> [Float; 2 * Self::LINKS] {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        [self.m; 2 * Self::LINKS]
    }
    fn force(&self) -> [Float; 2 * Self::LINKS] {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let mut f = [0.0; 2 * Self::LINKS];
        for i in 0..Self::LINKS {
            f[2 * i + 1] = -self.m * self.g;
        }
        f
    }
    fn constraints(&self, q: [Float; 2 * Self::LINKS]) -> [Float; Self::LINKS] {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let mut g = [0.0; Self::LINKS];
        g[0] = q[0] * q[0] + q[1] * q[1] - self.l * self.l;
        for i in 1..Self::LINKS {
            g[i] = (q[2 * i] - q[2 * i - 2]).powi(2)
                + (q[2 * i + 1] - q[2 * i - 1]).powi(2) - self.l * self.l;
        }
        g
    }
}
#[allow(unused_variables, unused_mut, clippy::all)]
impl ::zeitner::__private::ConstrainedSystem<4, 2> for Chain2 {
    const POSITION_CONSTRAINTS: usize = 2;
    const MASS_IS_CONSTANT: bool = true;
    const DYNAMICS_DEPEND_ON_VELOCITY: bool = false;
    const SUMMARY: ::zeitner::__private::SceneSummary = ::zeitner::__private::SceneSummary {
        coordinates: 4,
        position_constraints: 2,
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
                    adds: 1u64,
                    muls: 1u64,
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
                    adds: 6u64,
                    muls: 5u64,
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
                        rows: 2,
                        cols: 4,
                        nonzeros: &[(0, 0), (0, 1), (1, 0), (1, 1), (1, 2), (1, 3)],
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
                        rows: 2,
                        cols: 1,
                        nonzeros: &[(0, 0), (1, 0)],
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
                        rows: 2,
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
                        rows: 2,
                        cols: 4,
                        nonzeros: &[(0, 0), (0, 1), (1, 0), (1, 1), (1, 2), (1, 3)],
                    },
                    ::zeitner::__private::BlockSummary {
                        name: "b",
                        rows: 2,
                        cols: 1,
                        nonzeros: &[(0, 0), (1, 0)],
                    },
                ],
                ops: ::zeitner::__private::OpCounts {
                    adds: 13u64,
                    muls: 19u64,
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
        ],
    };
    type Mass = ::zeitner::__private::DiagonalMass<4>;
    type Storage = ::zeitner::__private::Dense;
    const SPARSITY: ::core::option::Option<::zeitner::__private::Sparsity> = ::core::option::Option::Some(::zeitner::__private::Sparsity {
        constraint_jacobian: &[(0, 0), (0, 1), (1, 0), (1, 1), (1, 2), (1, 3)],
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
        let s0 = -(self.m * self.g);
        let mut f = ::zeitner::__private::Vector::<4>::zeros();
        f[1] = s0;
        f[3] = s0;
        f
    }
    #[inline]
    fn constraint_residual(
        &self,
        q: &::zeitner::__private::Vector<4>,
        v: &::zeitner::__private::Vector<4>,
        t: ::zeitner::__private::Float,
    ) -> ::zeitner::__private::Vector<2> {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let s0 = self.l.powi(2);
        let mut g = ::zeitner::__private::Vector::<2>::zeros();
        g[0] = q[0].powi(2) + q[1].powi(2) - s0;
        g[1] = (q[2] - q[0]).powi(2) + (q[3] - q[1]).powi(2) - s0;
        g
    }
    #[inline]
    fn constraint_jacobian(
        &self,
        q: &::zeitner::__private::Vector<4>,
        v: &::zeitner::__private::Vector<4>,
        t: ::zeitner::__private::Float,
    ) -> ::zeitner::__private::Matrix<2, 4> {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let s0 = 2.0 * (q[2] - q[0]);
        let s1 = 2.0 * (q[3] - q[1]);
        let mut g = ::zeitner::__private::Matrix::<2, 4>::zeros();
        g[(0, 0)] = 2.0 * q[0];
        g[(0, 1)] = 2.0 * q[1];
        g[(1, 0)] = -s0;
        g[(1, 1)] = -s1;
        g[(1, 2)] = s0;
        g[(1, 3)] = s1;
        g
    }
    #[inline]
    fn constraint_rate(
        &self,
        q: &::zeitner::__private::Vector<4>,
        v: &::zeitner::__private::Vector<4>,
        t: ::zeitner::__private::Float,
    ) -> ::zeitner::__private::Vector<2> {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let s0 = 2.0 * (q[2] - q[0]);
        let s1 = 2.0 * (q[3] - q[1]);
        let mut w = ::zeitner::__private::Vector::<2>::zeros();
        w[0] = 2.0 * q[0] * v[0] + 2.0 * q[1] * v[1];
        w[1] = -(s0 * v[0]) - s1 * v[1] + s0 * v[2] + s1 * v[3];
        w
    }
    #[inline]
    fn constraint_acceleration_bias(
        &self,
        q: &::zeitner::__private::Vector<4>,
        v: &::zeitner::__private::Vector<4>,
        t: ::zeitner::__private::Float,
    ) -> ::zeitner::__private::Vector<2> {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let s0 = 2.0 * v[0];
        let s1 = 2.0 * v[1];
        let mut b = ::zeitner::__private::Vector::<2>::zeros();
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
        ::zeitner::__private::Matrix<2, 4>,
        ::zeitner::__private::Vector<2>,
    ) {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let s0 = -(self.m * self.g);
        let s1 = 2.0 * (q[2] - q[0]);
        let s2 = 2.0 * (q[3] - q[1]);
        let s3 = 2.0 * v[0];
        let s4 = 2.0 * v[1];
        let mut m = ::zeitner::__private::Vector::<4>::zeros();
        let mut f = ::zeitner::__private::Vector::<4>::zeros();
        let mut g = ::zeitner::__private::Matrix::<2, 4>::zeros();
        let mut b = ::zeitner::__private::Vector::<2>::zeros();
        m[0] = self.m;
        m[1] = self.m;
        m[2] = self.m;
        m[3] = self.m;
        f[1] = s0;
        f[3] = s0;
        g[(0, 0)] = 2.0 * q[0];
        g[(0, 1)] = 2.0 * q[1];
        g[(1, 0)] = -s1;
        g[(1, 1)] = -s2;
        g[(1, 2)] = s1;
        g[(1, 3)] = s2;
        b[0] = v[0] * s3 + v[1] * s4;
        b[1] = v[0] * (-2.0 * v[2] - -2.0 * v[0]) + v[1] * (-2.0 * v[3] - -2.0 * v[1])
            + v[2] * (2.0 * v[2] - s3) + v[3] * (2.0 * v[3] - s4);
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
        lambda: &::zeitner::__private::Vector<2>,
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
        lambda: &::zeitner::__private::Vector<2>,
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
#[allow(dead_code)]
impl Chain4 {
    const LINKS: usize = 4;
    fn mass(&self) -> [Float; 2 * Self::LINKS] {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        [self.m; 2 * Self::LINKS]
    }
    fn force(&self) -> [Float; 2 * Self::LINKS] {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let mut f = [0.0; 2 * Self::LINKS];
        for i in 0..Self::LINKS {
            f[2 * i + 1] = -self.m * self.g;
        }
        f
    }
    fn constraints(&self, q: [Float; 2 * Self::LINKS]) -> [Float; Self::LINKS] {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let mut g = [0.0; Self::LINKS];
        g[0] = q[0] * q[0] + q[1] * q[1] - self.l * self.l;
        for i in 1..Self::LINKS {
            g[i] = (q[2 * i] - q[2 * i - 2]).powi(2)
                + (q[2 * i + 1] - q[2 * i - 1]).powi(2) - self.l * self.l;
        }
        g
    }
}
#[allow(unused_variables, unused_mut, clippy::all)]
impl ::zeitner::__private::ConstrainedSystem<8, 4> for Chain4 {
    const POSITION_CONSTRAINTS: usize = 4;
    const MASS_IS_CONSTANT: bool = true;
    const DYNAMICS_DEPEND_ON_VELOCITY: bool = false;
    const SUMMARY: ::zeitner::__private::SceneSummary = ::zeitner::__private::SceneSummary {
        coordinates: 8,
        position_constraints: 4,
        velocity_constraints: 0,
        mass: ::zeitner::__private::MassKind::ConstantDiagonal,
        time_dependent: false,
        functions: &[
            ::zeitner::__private::FunctionSummary {
                name: "mass_matrix",
                blocks: &[
                    ::zeitner::__private::BlockSummary {
                        name: "m",
                        rows: 8,
                        cols: 1,
                        nonzeros: &[
                            (0, 0),
                            (1, 0),
                            (2, 0),
                            (3, 0),
                            (4, 0),
                            (5, 0),
                            (6, 0),
                            (7, 0),
                        ],
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
                        rows: 8,
                        cols: 1,
                        nonzeros: &[(1, 0), (3, 0), (5, 0), (7, 0)],
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
                    adds: 4u64,
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
                    adds: 14u64,
                    muls: 9u64,
                    divs: 0u64,
                    transcendental: 0u64,
                    opaque_calls: 0u64,
                },
                ops_unshared: ::zeitner::__private::OpCounts {
                    adds: 14u64,
                    muls: 12u64,
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
                        cols: 8,
                        nonzeros: &[
                            (0, 0),
                            (0, 1),
                            (1, 0),
                            (1, 1),
                            (1, 2),
                            (1, 3),
                            (2, 2),
                            (2, 3),
                            (2, 4),
                            (2, 5),
                            (3, 4),
                            (3, 5),
                            (3, 6),
                            (3, 7),
                        ],
                    },
                ],
                ops: ::zeitner::__private::OpCounts {
                    adds: 12u64,
                    muls: 8u64,
                    divs: 0u64,
                    transcendental: 0u64,
                    opaque_calls: 0u64,
                },
                ops_unshared: ::zeitner::__private::OpCounts {
                    adds: 18u64,
                    muls: 14u64,
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
                    adds: 19u64,
                    muls: 22u64,
                    divs: 0u64,
                    transcendental: 0u64,
                    opaque_calls: 0u64,
                },
                ops_unshared: ::zeitner::__private::OpCounts {
                    adds: 25u64,
                    muls: 28u64,
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
                        nonzeros: &[(0, 0), (1, 0), (2, 0), (3, 0)],
                    },
                ],
                ops: ::zeitner::__private::OpCounts {
                    adds: 22u64,
                    muls: 30u64,
                    divs: 0u64,
                    transcendental: 0u64,
                    opaque_calls: 0u64,
                },
                ops_unshared: ::zeitner::__private::OpCounts {
                    adds: 22u64,
                    muls: 40u64,
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
                        rows: 8,
                        cols: 1,
                        nonzeros: &[
                            (0, 0),
                            (1, 0),
                            (2, 0),
                            (3, 0),
                            (4, 0),
                            (5, 0),
                            (6, 0),
                            (7, 0),
                        ],
                    },
                    ::zeitner::__private::BlockSummary {
                        name: "f",
                        rows: 8,
                        cols: 1,
                        nonzeros: &[(1, 0), (3, 0), (5, 0), (7, 0)],
                    },
                    ::zeitner::__private::BlockSummary {
                        name: "g",
                        rows: 4,
                        cols: 8,
                        nonzeros: &[
                            (0, 0),
                            (0, 1),
                            (1, 0),
                            (1, 1),
                            (1, 2),
                            (1, 3),
                            (2, 2),
                            (2, 3),
                            (2, 4),
                            (2, 5),
                            (3, 4),
                            (3, 5),
                            (3, 6),
                            (3, 7),
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
                    adds: 35u64,
                    muls: 39u64,
                    divs: 0u64,
                    transcendental: 0u64,
                    opaque_calls: 0u64,
                },
                ops_unshared: ::zeitner::__private::OpCounts {
                    adds: 44u64,
                    muls: 58u64,
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
                        rows: 8,
                        cols: 8,
                        nonzeros: &[],
                    },
                    ::zeitner::__private::BlockSummary {
                        name: "dv",
                        rows: 8,
                        cols: 8,
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
                        rows: 8,
                        cols: 8,
                        nonzeros: &[
                            (0, 0),
                            (0, 2),
                            (1, 1),
                            (1, 3),
                            (2, 0),
                            (2, 2),
                            (2, 4),
                            (3, 1),
                            (3, 3),
                            (3, 5),
                            (4, 2),
                            (4, 4),
                            (4, 6),
                            (5, 3),
                            (5, 5),
                            (5, 7),
                            (6, 4),
                            (6, 6),
                            (7, 5),
                            (7, 7),
                        ],
                    },
                    ::zeitner::__private::BlockSummary {
                        name: "dv",
                        rows: 8,
                        cols: 8,
                        nonzeros: &[],
                    },
                ],
                ops: ::zeitner::__private::OpCounts {
                    adds: 6u64,
                    muls: 7u64,
                    divs: 0u64,
                    transcendental: 0u64,
                    opaque_calls: 0u64,
                },
                ops_unshared: ::zeitner::__private::OpCounts {
                    adds: 12u64,
                    muls: 26u64,
                    divs: 0u64,
                    transcendental: 0u64,
                    opaque_calls: 0u64,
                },
            },
        ],
    };
    type Mass = ::zeitner::__private::DiagonalMass<8>;
    type Storage = ::zeitner::__private::Dense;
    const SPARSITY: ::core::option::Option<::zeitner::__private::Sparsity> = ::core::option::Option::Some(::zeitner::__private::Sparsity {
        constraint_jacobian: &[
            (0, 0),
            (0, 1),
            (1, 0),
            (1, 1),
            (1, 2),
            (1, 3),
            (2, 2),
            (2, 3),
            (2, 4),
            (2, 5),
            (3, 4),
            (3, 5),
            (3, 6),
            (3, 7),
        ],
        force_jacobians: [&[], &[]],
        constraint_force_jacobians: [
            &[
                (0, 0),
                (0, 2),
                (1, 1),
                (1, 3),
                (2, 0),
                (2, 2),
                (2, 4),
                (3, 1),
                (3, 3),
                (3, 5),
                (4, 2),
                (4, 4),
                (4, 6),
                (5, 3),
                (5, 5),
                (5, 7),
                (6, 4),
                (6, 6),
                (7, 5),
                (7, 7),
            ],
            &[],
        ],
    });
    #[inline]
    fn mass_matrix(
        &self,
        q: &::zeitner::__private::Vector<8>,
        t: ::zeitner::__private::Float,
    ) -> Self::Mass {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let mut m = ::zeitner::__private::Vector::<8>::zeros();
        m[0] = self.m;
        m[1] = self.m;
        m[2] = self.m;
        m[3] = self.m;
        m[4] = self.m;
        m[5] = self.m;
        m[6] = self.m;
        m[7] = self.m;
        ::zeitner::__private::DiagonalMass(m)
    }
    #[inline]
    fn applied_force(
        &self,
        q: &::zeitner::__private::Vector<8>,
        v: &::zeitner::__private::Vector<8>,
        t: ::zeitner::__private::Float,
    ) -> ::zeitner::__private::Vector<8> {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let s0 = -(self.m * self.g);
        let mut f = ::zeitner::__private::Vector::<8>::zeros();
        f[1] = s0;
        f[3] = s0;
        f[5] = s0;
        f[7] = s0;
        f
    }
    #[inline]
    fn constraint_residual(
        &self,
        q: &::zeitner::__private::Vector<8>,
        v: &::zeitner::__private::Vector<8>,
        t: ::zeitner::__private::Float,
    ) -> ::zeitner::__private::Vector<4> {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let s0 = self.l.powi(2);
        let mut g = ::zeitner::__private::Vector::<4>::zeros();
        g[0] = q[0].powi(2) + q[1].powi(2) - s0;
        g[1] = (q[2] - q[0]).powi(2) + (q[3] - q[1]).powi(2) - s0;
        g[2] = (q[4] - q[2]).powi(2) + (q[5] - q[3]).powi(2) - s0;
        g[3] = (q[6] - q[4]).powi(2) + (q[7] - q[5]).powi(2) - s0;
        g
    }
    #[inline]
    fn constraint_jacobian(
        &self,
        q: &::zeitner::__private::Vector<8>,
        v: &::zeitner::__private::Vector<8>,
        t: ::zeitner::__private::Float,
    ) -> ::zeitner::__private::Matrix<4, 8> {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let s0 = 2.0 * (q[2] - q[0]);
        let s1 = 2.0 * (q[3] - q[1]);
        let s2 = 2.0 * (q[4] - q[2]);
        let s3 = 2.0 * (q[5] - q[3]);
        let s4 = 2.0 * (q[6] - q[4]);
        let s5 = 2.0 * (q[7] - q[5]);
        let mut g = ::zeitner::__private::Matrix::<4, 8>::zeros();
        g[(0, 0)] = 2.0 * q[0];
        g[(0, 1)] = 2.0 * q[1];
        g[(1, 0)] = -s0;
        g[(1, 1)] = -s1;
        g[(1, 2)] = s0;
        g[(1, 3)] = s1;
        g[(2, 2)] = -s2;
        g[(2, 3)] = -s3;
        g[(2, 4)] = s2;
        g[(2, 5)] = s3;
        g[(3, 4)] = -s4;
        g[(3, 5)] = -s5;
        g[(3, 6)] = s4;
        g[(3, 7)] = s5;
        g
    }
    #[inline]
    fn constraint_rate(
        &self,
        q: &::zeitner::__private::Vector<8>,
        v: &::zeitner::__private::Vector<8>,
        t: ::zeitner::__private::Float,
    ) -> ::zeitner::__private::Vector<4> {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let s0 = 2.0 * (q[2] - q[0]);
        let s1 = 2.0 * (q[3] - q[1]);
        let s2 = 2.0 * (q[4] - q[2]);
        let s3 = 2.0 * (q[5] - q[3]);
        let s4 = 2.0 * (q[6] - q[4]);
        let s5 = 2.0 * (q[7] - q[5]);
        let mut w = ::zeitner::__private::Vector::<4>::zeros();
        w[0] = 2.0 * q[0] * v[0] + 2.0 * q[1] * v[1];
        w[1] = -(s0 * v[0]) - s1 * v[1] + s0 * v[2] + s1 * v[3];
        w[2] = -(s2 * v[2]) - s3 * v[3] + s2 * v[4] + s3 * v[5];
        w[3] = -(s4 * v[4]) - s5 * v[5] + s4 * v[6] + s5 * v[7];
        w
    }
    #[inline]
    fn constraint_acceleration_bias(
        &self,
        q: &::zeitner::__private::Vector<8>,
        v: &::zeitner::__private::Vector<8>,
        t: ::zeitner::__private::Float,
    ) -> ::zeitner::__private::Vector<4> {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let s0 = 2.0 * v[0];
        let s1 = 2.0 * v[1];
        let s2 = -2.0 * v[2];
        let s3 = -2.0 * v[3];
        let s4 = 2.0 * v[2];
        let s5 = 2.0 * v[3];
        let s6 = -2.0 * v[4];
        let s7 = -2.0 * v[5];
        let s8 = 2.0 * v[4];
        let s9 = 2.0 * v[5];
        let mut b = ::zeitner::__private::Vector::<4>::zeros();
        b[0] = v[0] * s0 + v[1] * s1;
        b[1] = v[0] * (s2 - -2.0 * v[0]) + v[1] * (s3 - -2.0 * v[1]) + v[2] * (s4 - s0)
            + v[3] * (s5 - s1);
        b[2] = v[2] * (s6 - s2) + v[3] * (s7 - s3) + v[4] * (s8 - s4) + v[5] * (s9 - s5);
        b[3] = v[4] * (-2.0 * v[6] - s6) + v[5] * (-2.0 * v[7] - s7)
            + v[6] * (2.0 * v[6] - s8) + v[7] * (2.0 * v[7] - s9);
        b
    }
    #[inline]
    fn stage(
        &self,
        q: &::zeitner::__private::Vector<8>,
        v: &::zeitner::__private::Vector<8>,
        t: ::zeitner::__private::Float,
    ) -> (
        Self::Mass,
        ::zeitner::__private::Vector<8>,
        ::zeitner::__private::Matrix<4, 8>,
        ::zeitner::__private::Vector<4>,
    ) {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let s0 = -(self.m * self.g);
        let s1 = 2.0 * (q[2] - q[0]);
        let s2 = 2.0 * (q[3] - q[1]);
        let s3 = 2.0 * (q[4] - q[2]);
        let s4 = 2.0 * (q[5] - q[3]);
        let s5 = 2.0 * (q[6] - q[4]);
        let s6 = 2.0 * (q[7] - q[5]);
        let s7 = 2.0 * v[0];
        let s8 = 2.0 * v[1];
        let s9 = -2.0 * v[2];
        let s10 = -2.0 * v[3];
        let s11 = 2.0 * v[2];
        let s12 = 2.0 * v[3];
        let s13 = -2.0 * v[4];
        let s14 = -2.0 * v[5];
        let s15 = 2.0 * v[4];
        let s16 = 2.0 * v[5];
        let mut m = ::zeitner::__private::Vector::<8>::zeros();
        let mut f = ::zeitner::__private::Vector::<8>::zeros();
        let mut g = ::zeitner::__private::Matrix::<4, 8>::zeros();
        let mut b = ::zeitner::__private::Vector::<4>::zeros();
        m[0] = self.m;
        m[1] = self.m;
        m[2] = self.m;
        m[3] = self.m;
        m[4] = self.m;
        m[5] = self.m;
        m[6] = self.m;
        m[7] = self.m;
        f[1] = s0;
        f[3] = s0;
        f[5] = s0;
        f[7] = s0;
        g[(0, 0)] = 2.0 * q[0];
        g[(0, 1)] = 2.0 * q[1];
        g[(1, 0)] = -s1;
        g[(1, 1)] = -s2;
        g[(1, 2)] = s1;
        g[(1, 3)] = s2;
        g[(2, 2)] = -s3;
        g[(2, 3)] = -s4;
        g[(2, 4)] = s3;
        g[(2, 5)] = s4;
        g[(3, 4)] = -s5;
        g[(3, 5)] = -s6;
        g[(3, 6)] = s5;
        g[(3, 7)] = s6;
        b[0] = v[0] * s7 + v[1] * s8;
        b[1] = v[0] * (s9 - -2.0 * v[0]) + v[1] * (s10 - -2.0 * v[1]) + v[2] * (s11 - s7)
            + v[3] * (s12 - s8);
        b[2] = v[2] * (s13 - s9) + v[3] * (s14 - s10) + v[4] * (s15 - s11)
            + v[5] * (s16 - s12);
        b[3] = v[4] * (-2.0 * v[6] - s13) + v[5] * (-2.0 * v[7] - s14)
            + v[6] * (2.0 * v[6] - s15) + v[7] * (2.0 * v[7] - s16);
        (::zeitner::__private::DiagonalMass(m), f, g, b)
    }
    #[inline]
    fn force_jacobians(
        &self,
        q: &::zeitner::__private::Vector<8>,
        v: &::zeitner::__private::Vector<8>,
        t: ::zeitner::__private::Float,
    ) -> (::zeitner::__private::Matrix<8, 8>, ::zeitner::__private::Matrix<8, 8>) {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let mut dq = ::zeitner::__private::Matrix::<8, 8>::zeros();
        let mut dv = ::zeitner::__private::Matrix::<8, 8>::zeros();
        (dq, dv)
    }
    #[inline]
    fn constraint_force_jacobians(
        &self,
        q: &::zeitner::__private::Vector<8>,
        v: &::zeitner::__private::Vector<8>,
        t: ::zeitner::__private::Float,
        lambda: &::zeitner::__private::Vector<4>,
    ) -> (::zeitner::__private::Matrix<8, 8>, ::zeitner::__private::Matrix<8, 8>) {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let s0 = -2.0 * lambda[1];
        let s1 = 2.0 * lambda[0] - s0;
        let s2 = 2.0 * lambda[1];
        let s3 = -s2;
        let s4 = -2.0 * lambda[2];
        let s5 = s2 - s4;
        let s6 = 2.0 * lambda[2];
        let s7 = -s6;
        let s8 = -2.0 * lambda[3];
        let s9 = s6 - s8;
        let s10 = 2.0 * lambda[3];
        let s11 = -s10;
        let mut dq = ::zeitner::__private::Matrix::<8, 8>::zeros();
        let mut dv = ::zeitner::__private::Matrix::<8, 8>::zeros();
        dq[(0, 0)] = s1;
        dq[(0, 2)] = s3;
        dq[(1, 1)] = s1;
        dq[(1, 3)] = s3;
        dq[(2, 0)] = s0;
        dq[(2, 2)] = s5;
        dq[(2, 4)] = s7;
        dq[(3, 1)] = s0;
        dq[(3, 3)] = s5;
        dq[(3, 5)] = s7;
        dq[(4, 2)] = s4;
        dq[(4, 4)] = s9;
        dq[(4, 6)] = s11;
        dq[(5, 3)] = s4;
        dq[(5, 5)] = s9;
        dq[(5, 7)] = s11;
        dq[(6, 4)] = s8;
        dq[(6, 6)] = s10;
        dq[(7, 5)] = s8;
        dq[(7, 7)] = s10;
        (dq, dv)
    }
    #[inline]
    fn constraint_jacobian_nonzeros(
        &self,
        q: &::zeitner::__private::Vector<8>,
        v: &::zeitner::__private::Vector<8>,
        t: ::zeitner::__private::Float,
        values: &mut [::zeitner::__private::Float],
    ) {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let s0 = 2.0 * (q[2] - q[0]);
        let s1 = 2.0 * (q[3] - q[1]);
        let s2 = 2.0 * (q[4] - q[2]);
        let s3 = 2.0 * (q[5] - q[3]);
        let s4 = 2.0 * (q[6] - q[4]);
        let s5 = 2.0 * (q[7] - q[5]);
        values[0] = 2.0 * q[0];
        values[1] = 2.0 * q[1];
        values[2] = -s0;
        values[3] = -s1;
        values[4] = s0;
        values[5] = s1;
        values[6] = -s2;
        values[7] = -s3;
        values[8] = s2;
        values[9] = s3;
        values[10] = -s4;
        values[11] = -s5;
        values[12] = s4;
        values[13] = s5;
    }
    #[inline]
    fn force_jacobian_nonzeros(
        &self,
        q: &::zeitner::__private::Vector<8>,
        v: &::zeitner::__private::Vector<8>,
        t: ::zeitner::__private::Float,
        values: &mut [::zeitner::__private::Float],
    ) {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
    }
    #[inline]
    fn constraint_force_jacobian_nonzeros(
        &self,
        q: &::zeitner::__private::Vector<8>,
        v: &::zeitner::__private::Vector<8>,
        t: ::zeitner::__private::Float,
        lambda: &::zeitner::__private::Vector<4>,
        values: &mut [::zeitner::__private::Float],
    ) {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let s0 = -2.0 * lambda[1];
        let s1 = 2.0 * lambda[0] - s0;
        let s2 = 2.0 * lambda[1];
        let s3 = -s2;
        let s4 = -2.0 * lambda[2];
        let s5 = s2 - s4;
        let s6 = 2.0 * lambda[2];
        let s7 = -s6;
        let s8 = -2.0 * lambda[3];
        let s9 = s6 - s8;
        let s10 = 2.0 * lambda[3];
        let s11 = -s10;
        values[0] = s1;
        values[1] = s3;
        values[2] = s1;
        values[3] = s3;
        values[4] = s0;
        values[5] = s5;
        values[6] = s7;
        values[7] = s0;
        values[8] = s5;
        values[9] = s7;
        values[10] = s4;
        values[11] = s9;
        values[12] = s11;
        values[13] = s4;
        values[14] = s9;
        values[15] = s11;
        values[16] = s8;
        values[17] = s10;
        values[18] = s8;
        values[19] = s10;
    }
}
#[allow(dead_code)]
impl Chain8 {
    const LINKS: usize = 8;
    fn mass(&self) -> [Float; 2 * Self::LINKS] {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        [self.m; 2 * Self::LINKS]
    }
    fn force(&self) -> [Float; 2 * Self::LINKS] {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let mut f = [0.0; 2 * Self::LINKS];
        for i in 0..Self::LINKS {
            f[2 * i + 1] = -self.m * self.g;
        }
        f
    }
    fn constraints(&self, q: [Float; 2 * Self::LINKS]) -> [Float; Self::LINKS] {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let mut g = [0.0; Self::LINKS];
        g[0] = q[0] * q[0] + q[1] * q[1] - self.l * self.l;
        for i in 1..Self::LINKS {
            g[i] = (q[2 * i] - q[2 * i - 2]).powi(2)
                + (q[2 * i + 1] - q[2 * i - 1]).powi(2) - self.l * self.l;
        }
        g
    }
}
#[allow(unused_variables, unused_mut, clippy::all)]
impl ::zeitner::__private::ConstrainedSystem<16, 8> for Chain8 {
    const POSITION_CONSTRAINTS: usize = 8;
    const MASS_IS_CONSTANT: bool = true;
    const DYNAMICS_DEPEND_ON_VELOCITY: bool = false;
    const SUMMARY: ::zeitner::__private::SceneSummary = ::zeitner::__private::SceneSummary {
        coordinates: 16,
        position_constraints: 8,
        velocity_constraints: 0,
        mass: ::zeitner::__private::MassKind::ConstantDiagonal,
        time_dependent: false,
        functions: &[
            ::zeitner::__private::FunctionSummary {
                name: "mass_matrix",
                blocks: &[
                    ::zeitner::__private::BlockSummary {
                        name: "m",
                        rows: 16,
                        cols: 1,
                        nonzeros: &[
                            (0, 0),
                            (1, 0),
                            (2, 0),
                            (3, 0),
                            (4, 0),
                            (5, 0),
                            (6, 0),
                            (7, 0),
                            (8, 0),
                            (9, 0),
                            (10, 0),
                            (11, 0),
                            (12, 0),
                            (13, 0),
                            (14, 0),
                            (15, 0),
                        ],
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
                        rows: 16,
                        cols: 1,
                        nonzeros: &[
                            (1, 0),
                            (3, 0),
                            (5, 0),
                            (7, 0),
                            (9, 0),
                            (11, 0),
                            (13, 0),
                            (15, 0),
                        ],
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
                    adds: 8u64,
                    muls: 8u64,
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
                        rows: 8,
                        cols: 1,
                        nonzeros: &[
                            (0, 0),
                            (1, 0),
                            (2, 0),
                            (3, 0),
                            (4, 0),
                            (5, 0),
                            (6, 0),
                            (7, 0),
                        ],
                    },
                ],
                ops: ::zeitner::__private::OpCounts {
                    adds: 30u64,
                    muls: 17u64,
                    divs: 0u64,
                    transcendental: 0u64,
                    opaque_calls: 0u64,
                },
                ops_unshared: ::zeitner::__private::OpCounts {
                    adds: 30u64,
                    muls: 24u64,
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
                        rows: 8,
                        cols: 16,
                        nonzeros: &[
                            (0, 0),
                            (0, 1),
                            (1, 0),
                            (1, 1),
                            (1, 2),
                            (1, 3),
                            (2, 2),
                            (2, 3),
                            (2, 4),
                            (2, 5),
                            (3, 4),
                            (3, 5),
                            (3, 6),
                            (3, 7),
                            (4, 6),
                            (4, 7),
                            (4, 8),
                            (4, 9),
                            (5, 8),
                            (5, 9),
                            (5, 10),
                            (5, 11),
                            (6, 10),
                            (6, 11),
                            (6, 12),
                            (6, 13),
                            (7, 12),
                            (7, 13),
                            (7, 14),
                            (7, 15),
                        ],
                    },
                ],
                ops: ::zeitner::__private::OpCounts {
                    adds: 28u64,
                    muls: 16u64,
                    divs: 0u64,
                    transcendental: 0u64,
                    opaque_calls: 0u64,
                },
                ops_unshared: ::zeitner::__private::OpCounts {
                    adds: 42u64,
                    muls: 30u64,
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
                        rows: 8,
                        cols: 1,
                        nonzeros: &[
                            (0, 0),
                            (1, 0),
                            (2, 0),
                            (3, 0),
                            (4, 0),
                            (5, 0),
                            (6, 0),
                            (7, 0),
                        ],
                    },
                ],
                ops: ::zeitner::__private::OpCounts {
                    adds: 43u64,
                    muls: 46u64,
                    divs: 0u64,
                    transcendental: 0u64,
                    opaque_calls: 0u64,
                },
                ops_unshared: ::zeitner::__private::OpCounts {
                    adds: 57u64,
                    muls: 60u64,
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
                        rows: 8,
                        cols: 1,
                        nonzeros: &[
                            (0, 0),
                            (1, 0),
                            (2, 0),
                            (3, 0),
                            (4, 0),
                            (5, 0),
                            (6, 0),
                            (7, 0),
                        ],
                    },
                ],
                ops: ::zeitner::__private::OpCounts {
                    adds: 50u64,
                    muls: 62u64,
                    divs: 0u64,
                    transcendental: 0u64,
                    opaque_calls: 0u64,
                },
                ops_unshared: ::zeitner::__private::OpCounts {
                    adds: 50u64,
                    muls: 88u64,
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
                        rows: 16,
                        cols: 1,
                        nonzeros: &[
                            (0, 0),
                            (1, 0),
                            (2, 0),
                            (3, 0),
                            (4, 0),
                            (5, 0),
                            (6, 0),
                            (7, 0),
                            (8, 0),
                            (9, 0),
                            (10, 0),
                            (11, 0),
                            (12, 0),
                            (13, 0),
                            (14, 0),
                            (15, 0),
                        ],
                    },
                    ::zeitner::__private::BlockSummary {
                        name: "f",
                        rows: 16,
                        cols: 1,
                        nonzeros: &[
                            (1, 0),
                            (3, 0),
                            (5, 0),
                            (7, 0),
                            (9, 0),
                            (11, 0),
                            (13, 0),
                            (15, 0),
                        ],
                    },
                    ::zeitner::__private::BlockSummary {
                        name: "g",
                        rows: 8,
                        cols: 16,
                        nonzeros: &[
                            (0, 0),
                            (0, 1),
                            (1, 0),
                            (1, 1),
                            (1, 2),
                            (1, 3),
                            (2, 2),
                            (2, 3),
                            (2, 4),
                            (2, 5),
                            (3, 4),
                            (3, 5),
                            (3, 6),
                            (3, 7),
                            (4, 6),
                            (4, 7),
                            (4, 8),
                            (4, 9),
                            (5, 8),
                            (5, 9),
                            (5, 10),
                            (5, 11),
                            (6, 10),
                            (6, 11),
                            (6, 12),
                            (6, 13),
                            (7, 12),
                            (7, 13),
                            (7, 14),
                            (7, 15),
                        ],
                    },
                    ::zeitner::__private::BlockSummary {
                        name: "b",
                        rows: 8,
                        cols: 1,
                        nonzeros: &[
                            (0, 0),
                            (1, 0),
                            (2, 0),
                            (3, 0),
                            (4, 0),
                            (5, 0),
                            (6, 0),
                            (7, 0),
                        ],
                    },
                ],
                ops: ::zeitner::__private::OpCounts {
                    adds: 79u64,
                    muls: 79u64,
                    divs: 0u64,
                    transcendental: 0u64,
                    opaque_calls: 0u64,
                },
                ops_unshared: ::zeitner::__private::OpCounts {
                    adds: 100u64,
                    muls: 126u64,
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
                        rows: 16,
                        cols: 16,
                        nonzeros: &[],
                    },
                    ::zeitner::__private::BlockSummary {
                        name: "dv",
                        rows: 16,
                        cols: 16,
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
                        rows: 16,
                        cols: 16,
                        nonzeros: &[
                            (0, 0),
                            (0, 2),
                            (1, 1),
                            (1, 3),
                            (2, 0),
                            (2, 2),
                            (2, 4),
                            (3, 1),
                            (3, 3),
                            (3, 5),
                            (4, 2),
                            (4, 4),
                            (4, 6),
                            (5, 3),
                            (5, 5),
                            (5, 7),
                            (6, 4),
                            (6, 6),
                            (6, 8),
                            (7, 5),
                            (7, 7),
                            (7, 9),
                            (8, 6),
                            (8, 8),
                            (8, 10),
                            (9, 7),
                            (9, 9),
                            (9, 11),
                            (10, 8),
                            (10, 10),
                            (10, 12),
                            (11, 9),
                            (11, 11),
                            (11, 13),
                            (12, 10),
                            (12, 12),
                            (12, 14),
                            (13, 11),
                            (13, 13),
                            (13, 15),
                            (14, 12),
                            (14, 14),
                            (15, 13),
                            (15, 15),
                        ],
                    },
                    ::zeitner::__private::BlockSummary {
                        name: "dv",
                        rows: 16,
                        cols: 16,
                        nonzeros: &[],
                    },
                ],
                ops: ::zeitner::__private::OpCounts {
                    adds: 14u64,
                    muls: 15u64,
                    divs: 0u64,
                    transcendental: 0u64,
                    opaque_calls: 0u64,
                },
                ops_unshared: ::zeitner::__private::OpCounts {
                    adds: 28u64,
                    muls: 58u64,
                    divs: 0u64,
                    transcendental: 0u64,
                    opaque_calls: 0u64,
                },
            },
        ],
    };
    type Mass = ::zeitner::__private::DiagonalMass<16>;
    type Storage = ::zeitner::__private::Dense;
    const SPARSITY: ::core::option::Option<::zeitner::__private::Sparsity> = ::core::option::Option::Some(::zeitner::__private::Sparsity {
        constraint_jacobian: &[
            (0, 0),
            (0, 1),
            (1, 0),
            (1, 1),
            (1, 2),
            (1, 3),
            (2, 2),
            (2, 3),
            (2, 4),
            (2, 5),
            (3, 4),
            (3, 5),
            (3, 6),
            (3, 7),
            (4, 6),
            (4, 7),
            (4, 8),
            (4, 9),
            (5, 8),
            (5, 9),
            (5, 10),
            (5, 11),
            (6, 10),
            (6, 11),
            (6, 12),
            (6, 13),
            (7, 12),
            (7, 13),
            (7, 14),
            (7, 15),
        ],
        force_jacobians: [&[], &[]],
        constraint_force_jacobians: [
            &[
                (0, 0),
                (0, 2),
                (1, 1),
                (1, 3),
                (2, 0),
                (2, 2),
                (2, 4),
                (3, 1),
                (3, 3),
                (3, 5),
                (4, 2),
                (4, 4),
                (4, 6),
                (5, 3),
                (5, 5),
                (5, 7),
                (6, 4),
                (6, 6),
                (6, 8),
                (7, 5),
                (7, 7),
                (7, 9),
                (8, 6),
                (8, 8),
                (8, 10),
                (9, 7),
                (9, 9),
                (9, 11),
                (10, 8),
                (10, 10),
                (10, 12),
                (11, 9),
                (11, 11),
                (11, 13),
                (12, 10),
                (12, 12),
                (12, 14),
                (13, 11),
                (13, 13),
                (13, 15),
                (14, 12),
                (14, 14),
                (15, 13),
                (15, 15),
            ],
            &[],
        ],
    });
    #[inline]
    fn mass_matrix(
        &self,
        q: &::zeitner::__private::Vector<16>,
        t: ::zeitner::__private::Float,
    ) -> Self::Mass {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let mut m = ::zeitner::__private::Vector::<16>::zeros();
        m[0] = self.m;
        m[1] = self.m;
        m[2] = self.m;
        m[3] = self.m;
        m[4] = self.m;
        m[5] = self.m;
        m[6] = self.m;
        m[7] = self.m;
        m[8] = self.m;
        m[9] = self.m;
        m[10] = self.m;
        m[11] = self.m;
        m[12] = self.m;
        m[13] = self.m;
        m[14] = self.m;
        m[15] = self.m;
        ::zeitner::__private::DiagonalMass(m)
    }
    #[inline]
    fn applied_force(
        &self,
        q: &::zeitner::__private::Vector<16>,
        v: &::zeitner::__private::Vector<16>,
        t: ::zeitner::__private::Float,
    ) -> ::zeitner::__private::Vector<16> {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let s0 = -(self.m * self.g);
        let mut f = ::zeitner::__private::Vector::<16>::zeros();
        f[1] = s0;
        f[3] = s0;
        f[5] = s0;
        f[7] = s0;
        f[9] = s0;
        f[11] = s0;
        f[13] = s0;
        f[15] = s0;
        f
    }
    #[inline]
    fn constraint_residual(
        &self,
        q: &::zeitner::__private::Vector<16>,
        v: &::zeitner::__private::Vector<16>,
        t: ::zeitner::__private::Float,
    ) -> ::zeitner::__private::Vector<8> {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let s0 = self.l.powi(2);
        let mut g = ::zeitner::__private::Vector::<8>::zeros();
        g[0] = q[0].powi(2) + q[1].powi(2) - s0;
        g[1] = (q[2] - q[0]).powi(2) + (q[3] - q[1]).powi(2) - s0;
        g[2] = (q[4] - q[2]).powi(2) + (q[5] - q[3]).powi(2) - s0;
        g[3] = (q[6] - q[4]).powi(2) + (q[7] - q[5]).powi(2) - s0;
        g[4] = (q[8] - q[6]).powi(2) + (q[9] - q[7]).powi(2) - s0;
        g[5] = (q[10] - q[8]).powi(2) + (q[11] - q[9]).powi(2) - s0;
        g[6] = (q[12] - q[10]).powi(2) + (q[13] - q[11]).powi(2) - s0;
        g[7] = (q[14] - q[12]).powi(2) + (q[15] - q[13]).powi(2) - s0;
        g
    }
    #[inline]
    fn constraint_jacobian(
        &self,
        q: &::zeitner::__private::Vector<16>,
        v: &::zeitner::__private::Vector<16>,
        t: ::zeitner::__private::Float,
    ) -> ::zeitner::__private::Matrix<8, 16> {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let s0 = 2.0 * (q[2] - q[0]);
        let s1 = 2.0 * (q[3] - q[1]);
        let s2 = 2.0 * (q[4] - q[2]);
        let s3 = 2.0 * (q[5] - q[3]);
        let s4 = 2.0 * (q[6] - q[4]);
        let s5 = 2.0 * (q[7] - q[5]);
        let s6 = 2.0 * (q[8] - q[6]);
        let s7 = 2.0 * (q[9] - q[7]);
        let s8 = 2.0 * (q[10] - q[8]);
        let s9 = 2.0 * (q[11] - q[9]);
        let s10 = 2.0 * (q[12] - q[10]);
        let s11 = 2.0 * (q[13] - q[11]);
        let s12 = 2.0 * (q[14] - q[12]);
        let s13 = 2.0 * (q[15] - q[13]);
        let mut g = ::zeitner::__private::Matrix::<8, 16>::zeros();
        g[(0, 0)] = 2.0 * q[0];
        g[(0, 1)] = 2.0 * q[1];
        g[(1, 0)] = -s0;
        g[(1, 1)] = -s1;
        g[(1, 2)] = s0;
        g[(1, 3)] = s1;
        g[(2, 2)] = -s2;
        g[(2, 3)] = -s3;
        g[(2, 4)] = s2;
        g[(2, 5)] = s3;
        g[(3, 4)] = -s4;
        g[(3, 5)] = -s5;
        g[(3, 6)] = s4;
        g[(3, 7)] = s5;
        g[(4, 6)] = -s6;
        g[(4, 7)] = -s7;
        g[(4, 8)] = s6;
        g[(4, 9)] = s7;
        g[(5, 8)] = -s8;
        g[(5, 9)] = -s9;
        g[(5, 10)] = s8;
        g[(5, 11)] = s9;
        g[(6, 10)] = -s10;
        g[(6, 11)] = -s11;
        g[(6, 12)] = s10;
        g[(6, 13)] = s11;
        g[(7, 12)] = -s12;
        g[(7, 13)] = -s13;
        g[(7, 14)] = s12;
        g[(7, 15)] = s13;
        g
    }
    #[inline]
    fn constraint_rate(
        &self,
        q: &::zeitner::__private::Vector<16>,
        v: &::zeitner::__private::Vector<16>,
        t: ::zeitner::__private::Float,
    ) -> ::zeitner::__private::Vector<8> {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let s0 = 2.0 * (q[2] - q[0]);
        let s1 = 2.0 * (q[3] - q[1]);
        let s2 = 2.0 * (q[4] - q[2]);
        let s3 = 2.0 * (q[5] - q[3]);
        let s4 = 2.0 * (q[6] - q[4]);
        let s5 = 2.0 * (q[7] - q[5]);
        let s6 = 2.0 * (q[8] - q[6]);
        let s7 = 2.0 * (q[9] - q[7]);
        let s8 = 2.0 * (q[10] - q[8]);
        let s9 = 2.0 * (q[11] - q[9]);
        let s10 = 2.0 * (q[12] - q[10]);
        let s11 = 2.0 * (q[13] - q[11]);
        let s12 = 2.0 * (q[14] - q[12]);
        let s13 = 2.0 * (q[15] - q[13]);
        let mut w = ::zeitner::__private::Vector::<8>::zeros();
        w[0] = 2.0 * q[0] * v[0] + 2.0 * q[1] * v[1];
        w[1] = -(s0 * v[0]) - s1 * v[1] + s0 * v[2] + s1 * v[3];
        w[2] = -(s2 * v[2]) - s3 * v[3] + s2 * v[4] + s3 * v[5];
        w[3] = -(s4 * v[4]) - s5 * v[5] + s4 * v[6] + s5 * v[7];
        w[4] = -(s6 * v[6]) - s7 * v[7] + s6 * v[8] + s7 * v[9];
        w[5] = -(s8 * v[8]) - s9 * v[9] + s8 * v[10] + s9 * v[11];
        w[6] = -(s10 * v[10]) - s11 * v[11] + s10 * v[12] + s11 * v[13];
        w[7] = -(s12 * v[12]) - s13 * v[13] + s12 * v[14] + s13 * v[15];
        w
    }
    #[inline]
    fn constraint_acceleration_bias(
        &self,
        q: &::zeitner::__private::Vector<16>,
        v: &::zeitner::__private::Vector<16>,
        t: ::zeitner::__private::Float,
    ) -> ::zeitner::__private::Vector<8> {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let s0 = 2.0 * v[0];
        let s1 = 2.0 * v[1];
        let s2 = -2.0 * v[2];
        let s3 = -2.0 * v[3];
        let s4 = 2.0 * v[2];
        let s5 = 2.0 * v[3];
        let s6 = -2.0 * v[4];
        let s7 = -2.0 * v[5];
        let s8 = 2.0 * v[4];
        let s9 = 2.0 * v[5];
        let s10 = -2.0 * v[6];
        let s11 = -2.0 * v[7];
        let s12 = 2.0 * v[6];
        let s13 = 2.0 * v[7];
        let s14 = -2.0 * v[8];
        let s15 = -2.0 * v[9];
        let s16 = 2.0 * v[8];
        let s17 = 2.0 * v[9];
        let s18 = -2.0 * v[10];
        let s19 = -2.0 * v[11];
        let s20 = 2.0 * v[10];
        let s21 = 2.0 * v[11];
        let s22 = -2.0 * v[12];
        let s23 = -2.0 * v[13];
        let s24 = 2.0 * v[12];
        let s25 = 2.0 * v[13];
        let mut b = ::zeitner::__private::Vector::<8>::zeros();
        b[0] = v[0] * s0 + v[1] * s1;
        b[1] = v[0] * (s2 - -2.0 * v[0]) + v[1] * (s3 - -2.0 * v[1]) + v[2] * (s4 - s0)
            + v[3] * (s5 - s1);
        b[2] = v[2] * (s6 - s2) + v[3] * (s7 - s3) + v[4] * (s8 - s4) + v[5] * (s9 - s5);
        b[3] = v[4] * (s10 - s6) + v[5] * (s11 - s7) + v[6] * (s12 - s8)
            + v[7] * (s13 - s9);
        b[4] = v[6] * (s14 - s10) + v[7] * (s15 - s11) + v[8] * (s16 - s12)
            + v[9] * (s17 - s13);
        b[5] = v[8] * (s18 - s14) + v[9] * (s19 - s15) + v[10] * (s20 - s16)
            + v[11] * (s21 - s17);
        b[6] = v[10] * (s22 - s18) + v[11] * (s23 - s19) + v[12] * (s24 - s20)
            + v[13] * (s25 - s21);
        b[7] = v[12] * (-2.0 * v[14] - s22) + v[13] * (-2.0 * v[15] - s23)
            + v[14] * (2.0 * v[14] - s24) + v[15] * (2.0 * v[15] - s25);
        b
    }
    #[inline]
    fn stage(
        &self,
        q: &::zeitner::__private::Vector<16>,
        v: &::zeitner::__private::Vector<16>,
        t: ::zeitner::__private::Float,
    ) -> (
        Self::Mass,
        ::zeitner::__private::Vector<16>,
        ::zeitner::__private::Matrix<8, 16>,
        ::zeitner::__private::Vector<8>,
    ) {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let s0 = -(self.m * self.g);
        let s1 = 2.0 * (q[2] - q[0]);
        let s2 = 2.0 * (q[3] - q[1]);
        let s3 = 2.0 * (q[4] - q[2]);
        let s4 = 2.0 * (q[5] - q[3]);
        let s5 = 2.0 * (q[6] - q[4]);
        let s6 = 2.0 * (q[7] - q[5]);
        let s7 = 2.0 * (q[8] - q[6]);
        let s8 = 2.0 * (q[9] - q[7]);
        let s9 = 2.0 * (q[10] - q[8]);
        let s10 = 2.0 * (q[11] - q[9]);
        let s11 = 2.0 * (q[12] - q[10]);
        let s12 = 2.0 * (q[13] - q[11]);
        let s13 = 2.0 * (q[14] - q[12]);
        let s14 = 2.0 * (q[15] - q[13]);
        let s15 = 2.0 * v[0];
        let s16 = 2.0 * v[1];
        let s17 = -2.0 * v[2];
        let s18 = -2.0 * v[3];
        let s19 = 2.0 * v[2];
        let s20 = 2.0 * v[3];
        let s21 = -2.0 * v[4];
        let s22 = -2.0 * v[5];
        let s23 = 2.0 * v[4];
        let s24 = 2.0 * v[5];
        let s25 = -2.0 * v[6];
        let s26 = -2.0 * v[7];
        let s27 = 2.0 * v[6];
        let s28 = 2.0 * v[7];
        let s29 = -2.0 * v[8];
        let s30 = -2.0 * v[9];
        let s31 = 2.0 * v[8];
        let s32 = 2.0 * v[9];
        let s33 = -2.0 * v[10];
        let s34 = -2.0 * v[11];
        let s35 = 2.0 * v[10];
        let s36 = 2.0 * v[11];
        let s37 = -2.0 * v[12];
        let s38 = -2.0 * v[13];
        let s39 = 2.0 * v[12];
        let s40 = 2.0 * v[13];
        let mut m = ::zeitner::__private::Vector::<16>::zeros();
        let mut f = ::zeitner::__private::Vector::<16>::zeros();
        let mut g = ::zeitner::__private::Matrix::<8, 16>::zeros();
        let mut b = ::zeitner::__private::Vector::<8>::zeros();
        m[0] = self.m;
        m[1] = self.m;
        m[2] = self.m;
        m[3] = self.m;
        m[4] = self.m;
        m[5] = self.m;
        m[6] = self.m;
        m[7] = self.m;
        m[8] = self.m;
        m[9] = self.m;
        m[10] = self.m;
        m[11] = self.m;
        m[12] = self.m;
        m[13] = self.m;
        m[14] = self.m;
        m[15] = self.m;
        f[1] = s0;
        f[3] = s0;
        f[5] = s0;
        f[7] = s0;
        f[9] = s0;
        f[11] = s0;
        f[13] = s0;
        f[15] = s0;
        g[(0, 0)] = 2.0 * q[0];
        g[(0, 1)] = 2.0 * q[1];
        g[(1, 0)] = -s1;
        g[(1, 1)] = -s2;
        g[(1, 2)] = s1;
        g[(1, 3)] = s2;
        g[(2, 2)] = -s3;
        g[(2, 3)] = -s4;
        g[(2, 4)] = s3;
        g[(2, 5)] = s4;
        g[(3, 4)] = -s5;
        g[(3, 5)] = -s6;
        g[(3, 6)] = s5;
        g[(3, 7)] = s6;
        g[(4, 6)] = -s7;
        g[(4, 7)] = -s8;
        g[(4, 8)] = s7;
        g[(4, 9)] = s8;
        g[(5, 8)] = -s9;
        g[(5, 9)] = -s10;
        g[(5, 10)] = s9;
        g[(5, 11)] = s10;
        g[(6, 10)] = -s11;
        g[(6, 11)] = -s12;
        g[(6, 12)] = s11;
        g[(6, 13)] = s12;
        g[(7, 12)] = -s13;
        g[(7, 13)] = -s14;
        g[(7, 14)] = s13;
        g[(7, 15)] = s14;
        b[0] = v[0] * s15 + v[1] * s16;
        b[1] = v[0] * (s17 - -2.0 * v[0]) + v[1] * (s18 - -2.0 * v[1])
            + v[2] * (s19 - s15) + v[3] * (s20 - s16);
        b[2] = v[2] * (s21 - s17) + v[3] * (s22 - s18) + v[4] * (s23 - s19)
            + v[5] * (s24 - s20);
        b[3] = v[4] * (s25 - s21) + v[5] * (s26 - s22) + v[6] * (s27 - s23)
            + v[7] * (s28 - s24);
        b[4] = v[6] * (s29 - s25) + v[7] * (s30 - s26) + v[8] * (s31 - s27)
            + v[9] * (s32 - s28);
        b[5] = v[8] * (s33 - s29) + v[9] * (s34 - s30) + v[10] * (s35 - s31)
            + v[11] * (s36 - s32);
        b[6] = v[10] * (s37 - s33) + v[11] * (s38 - s34) + v[12] * (s39 - s35)
            + v[13] * (s40 - s36);
        b[7] = v[12] * (-2.0 * v[14] - s37) + v[13] * (-2.0 * v[15] - s38)
            + v[14] * (2.0 * v[14] - s39) + v[15] * (2.0 * v[15] - s40);
        (::zeitner::__private::DiagonalMass(m), f, g, b)
    }
    #[inline]
    fn force_jacobians(
        &self,
        q: &::zeitner::__private::Vector<16>,
        v: &::zeitner::__private::Vector<16>,
        t: ::zeitner::__private::Float,
    ) -> (::zeitner::__private::Matrix<16, 16>, ::zeitner::__private::Matrix<16, 16>) {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let mut dq = ::zeitner::__private::Matrix::<16, 16>::zeros();
        let mut dv = ::zeitner::__private::Matrix::<16, 16>::zeros();
        (dq, dv)
    }
    #[inline]
    fn constraint_force_jacobians(
        &self,
        q: &::zeitner::__private::Vector<16>,
        v: &::zeitner::__private::Vector<16>,
        t: ::zeitner::__private::Float,
        lambda: &::zeitner::__private::Vector<8>,
    ) -> (::zeitner::__private::Matrix<16, 16>, ::zeitner::__private::Matrix<16, 16>) {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let s0 = -2.0 * lambda[1];
        let s1 = 2.0 * lambda[0] - s0;
        let s2 = 2.0 * lambda[1];
        let s3 = -s2;
        let s4 = -2.0 * lambda[2];
        let s5 = s2 - s4;
        let s6 = 2.0 * lambda[2];
        let s7 = -s6;
        let s8 = -2.0 * lambda[3];
        let s9 = s6 - s8;
        let s10 = 2.0 * lambda[3];
        let s11 = -s10;
        let s12 = -2.0 * lambda[4];
        let s13 = s10 - s12;
        let s14 = 2.0 * lambda[4];
        let s15 = -s14;
        let s16 = -2.0 * lambda[5];
        let s17 = s14 - s16;
        let s18 = 2.0 * lambda[5];
        let s19 = -s18;
        let s20 = -2.0 * lambda[6];
        let s21 = s18 - s20;
        let s22 = 2.0 * lambda[6];
        let s23 = -s22;
        let s24 = -2.0 * lambda[7];
        let s25 = s22 - s24;
        let s26 = 2.0 * lambda[7];
        let s27 = -s26;
        let mut dq = ::zeitner::__private::Matrix::<16, 16>::zeros();
        let mut dv = ::zeitner::__private::Matrix::<16, 16>::zeros();
        dq[(0, 0)] = s1;
        dq[(0, 2)] = s3;
        dq[(1, 1)] = s1;
        dq[(1, 3)] = s3;
        dq[(2, 0)] = s0;
        dq[(2, 2)] = s5;
        dq[(2, 4)] = s7;
        dq[(3, 1)] = s0;
        dq[(3, 3)] = s5;
        dq[(3, 5)] = s7;
        dq[(4, 2)] = s4;
        dq[(4, 4)] = s9;
        dq[(4, 6)] = s11;
        dq[(5, 3)] = s4;
        dq[(5, 5)] = s9;
        dq[(5, 7)] = s11;
        dq[(6, 4)] = s8;
        dq[(6, 6)] = s13;
        dq[(6, 8)] = s15;
        dq[(7, 5)] = s8;
        dq[(7, 7)] = s13;
        dq[(7, 9)] = s15;
        dq[(8, 6)] = s12;
        dq[(8, 8)] = s17;
        dq[(8, 10)] = s19;
        dq[(9, 7)] = s12;
        dq[(9, 9)] = s17;
        dq[(9, 11)] = s19;
        dq[(10, 8)] = s16;
        dq[(10, 10)] = s21;
        dq[(10, 12)] = s23;
        dq[(11, 9)] = s16;
        dq[(11, 11)] = s21;
        dq[(11, 13)] = s23;
        dq[(12, 10)] = s20;
        dq[(12, 12)] = s25;
        dq[(12, 14)] = s27;
        dq[(13, 11)] = s20;
        dq[(13, 13)] = s25;
        dq[(13, 15)] = s27;
        dq[(14, 12)] = s24;
        dq[(14, 14)] = s26;
        dq[(15, 13)] = s24;
        dq[(15, 15)] = s26;
        (dq, dv)
    }
    #[inline]
    fn constraint_jacobian_nonzeros(
        &self,
        q: &::zeitner::__private::Vector<16>,
        v: &::zeitner::__private::Vector<16>,
        t: ::zeitner::__private::Float,
        values: &mut [::zeitner::__private::Float],
    ) {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let s0 = 2.0 * (q[2] - q[0]);
        let s1 = 2.0 * (q[3] - q[1]);
        let s2 = 2.0 * (q[4] - q[2]);
        let s3 = 2.0 * (q[5] - q[3]);
        let s4 = 2.0 * (q[6] - q[4]);
        let s5 = 2.0 * (q[7] - q[5]);
        let s6 = 2.0 * (q[8] - q[6]);
        let s7 = 2.0 * (q[9] - q[7]);
        let s8 = 2.0 * (q[10] - q[8]);
        let s9 = 2.0 * (q[11] - q[9]);
        let s10 = 2.0 * (q[12] - q[10]);
        let s11 = 2.0 * (q[13] - q[11]);
        let s12 = 2.0 * (q[14] - q[12]);
        let s13 = 2.0 * (q[15] - q[13]);
        values[0] = 2.0 * q[0];
        values[1] = 2.0 * q[1];
        values[2] = -s0;
        values[3] = -s1;
        values[4] = s0;
        values[5] = s1;
        values[6] = -s2;
        values[7] = -s3;
        values[8] = s2;
        values[9] = s3;
        values[10] = -s4;
        values[11] = -s5;
        values[12] = s4;
        values[13] = s5;
        values[14] = -s6;
        values[15] = -s7;
        values[16] = s6;
        values[17] = s7;
        values[18] = -s8;
        values[19] = -s9;
        values[20] = s8;
        values[21] = s9;
        values[22] = -s10;
        values[23] = -s11;
        values[24] = s10;
        values[25] = s11;
        values[26] = -s12;
        values[27] = -s13;
        values[28] = s12;
        values[29] = s13;
    }
    #[inline]
    fn force_jacobian_nonzeros(
        &self,
        q: &::zeitner::__private::Vector<16>,
        v: &::zeitner::__private::Vector<16>,
        t: ::zeitner::__private::Float,
        values: &mut [::zeitner::__private::Float],
    ) {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
    }
    #[inline]
    fn constraint_force_jacobian_nonzeros(
        &self,
        q: &::zeitner::__private::Vector<16>,
        v: &::zeitner::__private::Vector<16>,
        t: ::zeitner::__private::Float,
        lambda: &::zeitner::__private::Vector<8>,
        values: &mut [::zeitner::__private::Float],
    ) {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let s0 = -2.0 * lambda[1];
        let s1 = 2.0 * lambda[0] - s0;
        let s2 = 2.0 * lambda[1];
        let s3 = -s2;
        let s4 = -2.0 * lambda[2];
        let s5 = s2 - s4;
        let s6 = 2.0 * lambda[2];
        let s7 = -s6;
        let s8 = -2.0 * lambda[3];
        let s9 = s6 - s8;
        let s10 = 2.0 * lambda[3];
        let s11 = -s10;
        let s12 = -2.0 * lambda[4];
        let s13 = s10 - s12;
        let s14 = 2.0 * lambda[4];
        let s15 = -s14;
        let s16 = -2.0 * lambda[5];
        let s17 = s14 - s16;
        let s18 = 2.0 * lambda[5];
        let s19 = -s18;
        let s20 = -2.0 * lambda[6];
        let s21 = s18 - s20;
        let s22 = 2.0 * lambda[6];
        let s23 = -s22;
        let s24 = -2.0 * lambda[7];
        let s25 = s22 - s24;
        let s26 = 2.0 * lambda[7];
        let s27 = -s26;
        values[0] = s1;
        values[1] = s3;
        values[2] = s1;
        values[3] = s3;
        values[4] = s0;
        values[5] = s5;
        values[6] = s7;
        values[7] = s0;
        values[8] = s5;
        values[9] = s7;
        values[10] = s4;
        values[11] = s9;
        values[12] = s11;
        values[13] = s4;
        values[14] = s9;
        values[15] = s11;
        values[16] = s8;
        values[17] = s13;
        values[18] = s15;
        values[19] = s8;
        values[20] = s13;
        values[21] = s15;
        values[22] = s12;
        values[23] = s17;
        values[24] = s19;
        values[25] = s12;
        values[26] = s17;
        values[27] = s19;
        values[28] = s16;
        values[29] = s21;
        values[30] = s23;
        values[31] = s16;
        values[32] = s21;
        values[33] = s23;
        values[34] = s20;
        values[35] = s25;
        values[36] = s27;
        values[37] = s20;
        values[38] = s25;
        values[39] = s27;
        values[40] = s24;
        values[41] = s26;
        values[42] = s24;
        values[43] = s26;
    }
}
#[allow(dead_code)]
impl Chain16 {
    const LINKS: usize = 16;
    fn mass(&self) -> [Float; 2 * Self::LINKS] {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        [self.m; 2 * Self::LINKS]
    }
    fn force(&self) -> [Float; 2 * Self::LINKS] {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let mut f = [0.0; 2 * Self::LINKS];
        for i in 0..Self::LINKS {
            f[2 * i + 1] = -self.m * self.g;
        }
        f
    }
    fn constraints(&self, q: [Float; 2 * Self::LINKS]) -> [Float; Self::LINKS] {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let mut g = [0.0; Self::LINKS];
        g[0] = q[0] * q[0] + q[1] * q[1] - self.l * self.l;
        for i in 1..Self::LINKS {
            g[i] = (q[2 * i] - q[2 * i - 2]).powi(2)
                + (q[2 * i + 1] - q[2 * i - 1]).powi(2) - self.l * self.l;
        }
        g
    }
}
#[allow(unused_variables, unused_mut, clippy::all)]
impl ::zeitner::__private::ConstrainedSystem<32, 16> for Chain16 {
    const POSITION_CONSTRAINTS: usize = 16;
    const MASS_IS_CONSTANT: bool = true;
    const DYNAMICS_DEPEND_ON_VELOCITY: bool = false;
    const SUMMARY: ::zeitner::__private::SceneSummary = ::zeitner::__private::SceneSummary {
        coordinates: 32,
        position_constraints: 16,
        velocity_constraints: 0,
        mass: ::zeitner::__private::MassKind::ConstantDiagonal,
        time_dependent: false,
        functions: &[
            ::zeitner::__private::FunctionSummary {
                name: "mass_matrix",
                blocks: &[
                    ::zeitner::__private::BlockSummary {
                        name: "m",
                        rows: 32,
                        cols: 1,
                        nonzeros: &[
                            (0, 0),
                            (1, 0),
                            (2, 0),
                            (3, 0),
                            (4, 0),
                            (5, 0),
                            (6, 0),
                            (7, 0),
                            (8, 0),
                            (9, 0),
                            (10, 0),
                            (11, 0),
                            (12, 0),
                            (13, 0),
                            (14, 0),
                            (15, 0),
                            (16, 0),
                            (17, 0),
                            (18, 0),
                            (19, 0),
                            (20, 0),
                            (21, 0),
                            (22, 0),
                            (23, 0),
                            (24, 0),
                            (25, 0),
                            (26, 0),
                            (27, 0),
                            (28, 0),
                            (29, 0),
                            (30, 0),
                            (31, 0),
                        ],
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
                        rows: 32,
                        cols: 1,
                        nonzeros: &[
                            (1, 0),
                            (3, 0),
                            (5, 0),
                            (7, 0),
                            (9, 0),
                            (11, 0),
                            (13, 0),
                            (15, 0),
                            (17, 0),
                            (19, 0),
                            (21, 0),
                            (23, 0),
                            (25, 0),
                            (27, 0),
                            (29, 0),
                            (31, 0),
                        ],
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
                    adds: 16u64,
                    muls: 16u64,
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
                        rows: 16,
                        cols: 1,
                        nonzeros: &[
                            (0, 0),
                            (1, 0),
                            (2, 0),
                            (3, 0),
                            (4, 0),
                            (5, 0),
                            (6, 0),
                            (7, 0),
                            (8, 0),
                            (9, 0),
                            (10, 0),
                            (11, 0),
                            (12, 0),
                            (13, 0),
                            (14, 0),
                            (15, 0),
                        ],
                    },
                ],
                ops: ::zeitner::__private::OpCounts {
                    adds: 62u64,
                    muls: 33u64,
                    divs: 0u64,
                    transcendental: 0u64,
                    opaque_calls: 0u64,
                },
                ops_unshared: ::zeitner::__private::OpCounts {
                    adds: 62u64,
                    muls: 48u64,
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
                        rows: 16,
                        cols: 32,
                        nonzeros: &[
                            (0, 0),
                            (0, 1),
                            (1, 0),
                            (1, 1),
                            (1, 2),
                            (1, 3),
                            (2, 2),
                            (2, 3),
                            (2, 4),
                            (2, 5),
                            (3, 4),
                            (3, 5),
                            (3, 6),
                            (3, 7),
                            (4, 6),
                            (4, 7),
                            (4, 8),
                            (4, 9),
                            (5, 8),
                            (5, 9),
                            (5, 10),
                            (5, 11),
                            (6, 10),
                            (6, 11),
                            (6, 12),
                            (6, 13),
                            (7, 12),
                            (7, 13),
                            (7, 14),
                            (7, 15),
                            (8, 14),
                            (8, 15),
                            (8, 16),
                            (8, 17),
                            (9, 16),
                            (9, 17),
                            (9, 18),
                            (9, 19),
                            (10, 18),
                            (10, 19),
                            (10, 20),
                            (10, 21),
                            (11, 20),
                            (11, 21),
                            (11, 22),
                            (11, 23),
                            (12, 22),
                            (12, 23),
                            (12, 24),
                            (12, 25),
                            (13, 24),
                            (13, 25),
                            (13, 26),
                            (13, 27),
                            (14, 26),
                            (14, 27),
                            (14, 28),
                            (14, 29),
                            (15, 28),
                            (15, 29),
                            (15, 30),
                            (15, 31),
                        ],
                    },
                ],
                ops: ::zeitner::__private::OpCounts {
                    adds: 60u64,
                    muls: 32u64,
                    divs: 0u64,
                    transcendental: 0u64,
                    opaque_calls: 0u64,
                },
                ops_unshared: ::zeitner::__private::OpCounts {
                    adds: 90u64,
                    muls: 62u64,
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
                        rows: 16,
                        cols: 1,
                        nonzeros: &[
                            (0, 0),
                            (1, 0),
                            (2, 0),
                            (3, 0),
                            (4, 0),
                            (5, 0),
                            (6, 0),
                            (7, 0),
                            (8, 0),
                            (9, 0),
                            (10, 0),
                            (11, 0),
                            (12, 0),
                            (13, 0),
                            (14, 0),
                            (15, 0),
                        ],
                    },
                ],
                ops: ::zeitner::__private::OpCounts {
                    adds: 91u64,
                    muls: 94u64,
                    divs: 0u64,
                    transcendental: 0u64,
                    opaque_calls: 0u64,
                },
                ops_unshared: ::zeitner::__private::OpCounts {
                    adds: 121u64,
                    muls: 124u64,
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
                        rows: 16,
                        cols: 1,
                        nonzeros: &[
                            (0, 0),
                            (1, 0),
                            (2, 0),
                            (3, 0),
                            (4, 0),
                            (5, 0),
                            (6, 0),
                            (7, 0),
                            (8, 0),
                            (9, 0),
                            (10, 0),
                            (11, 0),
                            (12, 0),
                            (13, 0),
                            (14, 0),
                            (15, 0),
                        ],
                    },
                ],
                ops: ::zeitner::__private::OpCounts {
                    adds: 106u64,
                    muls: 126u64,
                    divs: 0u64,
                    transcendental: 0u64,
                    opaque_calls: 0u64,
                },
                ops_unshared: ::zeitner::__private::OpCounts {
                    adds: 106u64,
                    muls: 184u64,
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
                        rows: 32,
                        cols: 1,
                        nonzeros: &[
                            (0, 0),
                            (1, 0),
                            (2, 0),
                            (3, 0),
                            (4, 0),
                            (5, 0),
                            (6, 0),
                            (7, 0),
                            (8, 0),
                            (9, 0),
                            (10, 0),
                            (11, 0),
                            (12, 0),
                            (13, 0),
                            (14, 0),
                            (15, 0),
                            (16, 0),
                            (17, 0),
                            (18, 0),
                            (19, 0),
                            (20, 0),
                            (21, 0),
                            (22, 0),
                            (23, 0),
                            (24, 0),
                            (25, 0),
                            (26, 0),
                            (27, 0),
                            (28, 0),
                            (29, 0),
                            (30, 0),
                            (31, 0),
                        ],
                    },
                    ::zeitner::__private::BlockSummary {
                        name: "f",
                        rows: 32,
                        cols: 1,
                        nonzeros: &[
                            (1, 0),
                            (3, 0),
                            (5, 0),
                            (7, 0),
                            (9, 0),
                            (11, 0),
                            (13, 0),
                            (15, 0),
                            (17, 0),
                            (19, 0),
                            (21, 0),
                            (23, 0),
                            (25, 0),
                            (27, 0),
                            (29, 0),
                            (31, 0),
                        ],
                    },
                    ::zeitner::__private::BlockSummary {
                        name: "g",
                        rows: 16,
                        cols: 32,
                        nonzeros: &[
                            (0, 0),
                            (0, 1),
                            (1, 0),
                            (1, 1),
                            (1, 2),
                            (1, 3),
                            (2, 2),
                            (2, 3),
                            (2, 4),
                            (2, 5),
                            (3, 4),
                            (3, 5),
                            (3, 6),
                            (3, 7),
                            (4, 6),
                            (4, 7),
                            (4, 8),
                            (4, 9),
                            (5, 8),
                            (5, 9),
                            (5, 10),
                            (5, 11),
                            (6, 10),
                            (6, 11),
                            (6, 12),
                            (6, 13),
                            (7, 12),
                            (7, 13),
                            (7, 14),
                            (7, 15),
                            (8, 14),
                            (8, 15),
                            (8, 16),
                            (8, 17),
                            (9, 16),
                            (9, 17),
                            (9, 18),
                            (9, 19),
                            (10, 18),
                            (10, 19),
                            (10, 20),
                            (10, 21),
                            (11, 20),
                            (11, 21),
                            (11, 22),
                            (11, 23),
                            (12, 22),
                            (12, 23),
                            (12, 24),
                            (12, 25),
                            (13, 24),
                            (13, 25),
                            (13, 26),
                            (13, 27),
                            (14, 26),
                            (14, 27),
                            (14, 28),
                            (14, 29),
                            (15, 28),
                            (15, 29),
                            (15, 30),
                            (15, 31),
                        ],
                    },
                    ::zeitner::__private::BlockSummary {
                        name: "b",
                        rows: 16,
                        cols: 1,
                        nonzeros: &[
                            (0, 0),
                            (1, 0),
                            (2, 0),
                            (3, 0),
                            (4, 0),
                            (5, 0),
                            (6, 0),
                            (7, 0),
                            (8, 0),
                            (9, 0),
                            (10, 0),
                            (11, 0),
                            (12, 0),
                            (13, 0),
                            (14, 0),
                            (15, 0),
                        ],
                    },
                ],
                ops: ::zeitner::__private::OpCounts {
                    adds: 167u64,
                    muls: 159u64,
                    divs: 0u64,
                    transcendental: 0u64,
                    opaque_calls: 0u64,
                },
                ops_unshared: ::zeitner::__private::OpCounts {
                    adds: 212u64,
                    muls: 262u64,
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
                        rows: 32,
                        cols: 32,
                        nonzeros: &[],
                    },
                    ::zeitner::__private::BlockSummary {
                        name: "dv",
                        rows: 32,
                        cols: 32,
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
                        rows: 32,
                        cols: 32,
                        nonzeros: &[
                            (0, 0),
                            (0, 2),
                            (1, 1),
                            (1, 3),
                            (2, 0),
                            (2, 2),
                            (2, 4),
                            (3, 1),
                            (3, 3),
                            (3, 5),
                            (4, 2),
                            (4, 4),
                            (4, 6),
                            (5, 3),
                            (5, 5),
                            (5, 7),
                            (6, 4),
                            (6, 6),
                            (6, 8),
                            (7, 5),
                            (7, 7),
                            (7, 9),
                            (8, 6),
                            (8, 8),
                            (8, 10),
                            (9, 7),
                            (9, 9),
                            (9, 11),
                            (10, 8),
                            (10, 10),
                            (10, 12),
                            (11, 9),
                            (11, 11),
                            (11, 13),
                            (12, 10),
                            (12, 12),
                            (12, 14),
                            (13, 11),
                            (13, 13),
                            (13, 15),
                            (14, 12),
                            (14, 14),
                            (14, 16),
                            (15, 13),
                            (15, 15),
                            (15, 17),
                            (16, 14),
                            (16, 16),
                            (16, 18),
                            (17, 15),
                            (17, 17),
                            (17, 19),
                            (18, 16),
                            (18, 18),
                            (18, 20),
                            (19, 17),
                            (19, 19),
                            (19, 21),
                            (20, 18),
                            (20, 20),
                            (20, 22),
                            (21, 19),
                            (21, 21),
                            (21, 23),
                            (22, 20),
                            (22, 22),
                            (22, 24),
                            (23, 21),
                            (23, 23),
                            (23, 25),
                            (24, 22),
                            (24, 24),
                            (24, 26),
                            (25, 23),
                            (25, 25),
                            (25, 27),
                            (26, 24),
                            (26, 26),
                            (26, 28),
                            (27, 25),
                            (27, 27),
                            (27, 29),
                            (28, 26),
                            (28, 28),
                            (28, 30),
                            (29, 27),
                            (29, 29),
                            (29, 31),
                            (30, 28),
                            (30, 30),
                            (31, 29),
                            (31, 31),
                        ],
                    },
                    ::zeitner::__private::BlockSummary {
                        name: "dv",
                        rows: 32,
                        cols: 32,
                        nonzeros: &[],
                    },
                ],
                ops: ::zeitner::__private::OpCounts {
                    adds: 30u64,
                    muls: 31u64,
                    divs: 0u64,
                    transcendental: 0u64,
                    opaque_calls: 0u64,
                },
                ops_unshared: ::zeitner::__private::OpCounts {
                    adds: 60u64,
                    muls: 122u64,
                    divs: 0u64,
                    transcendental: 0u64,
                    opaque_calls: 0u64,
                },
            },
        ],
    };
    type Mass = ::zeitner::__private::DiagonalMass<32>;
    type Storage = ::zeitner::__private::Dense;
    const SPARSITY: ::core::option::Option<::zeitner::__private::Sparsity> = ::core::option::Option::Some(::zeitner::__private::Sparsity {
        constraint_jacobian: &[
            (0, 0),
            (0, 1),
            (1, 0),
            (1, 1),
            (1, 2),
            (1, 3),
            (2, 2),
            (2, 3),
            (2, 4),
            (2, 5),
            (3, 4),
            (3, 5),
            (3, 6),
            (3, 7),
            (4, 6),
            (4, 7),
            (4, 8),
            (4, 9),
            (5, 8),
            (5, 9),
            (5, 10),
            (5, 11),
            (6, 10),
            (6, 11),
            (6, 12),
            (6, 13),
            (7, 12),
            (7, 13),
            (7, 14),
            (7, 15),
            (8, 14),
            (8, 15),
            (8, 16),
            (8, 17),
            (9, 16),
            (9, 17),
            (9, 18),
            (9, 19),
            (10, 18),
            (10, 19),
            (10, 20),
            (10, 21),
            (11, 20),
            (11, 21),
            (11, 22),
            (11, 23),
            (12, 22),
            (12, 23),
            (12, 24),
            (12, 25),
            (13, 24),
            (13, 25),
            (13, 26),
            (13, 27),
            (14, 26),
            (14, 27),
            (14, 28),
            (14, 29),
            (15, 28),
            (15, 29),
            (15, 30),
            (15, 31),
        ],
        force_jacobians: [&[], &[]],
        constraint_force_jacobians: [
            &[
                (0, 0),
                (0, 2),
                (1, 1),
                (1, 3),
                (2, 0),
                (2, 2),
                (2, 4),
                (3, 1),
                (3, 3),
                (3, 5),
                (4, 2),
                (4, 4),
                (4, 6),
                (5, 3),
                (5, 5),
                (5, 7),
                (6, 4),
                (6, 6),
                (6, 8),
                (7, 5),
                (7, 7),
                (7, 9),
                (8, 6),
                (8, 8),
                (8, 10),
                (9, 7),
                (9, 9),
                (9, 11),
                (10, 8),
                (10, 10),
                (10, 12),
                (11, 9),
                (11, 11),
                (11, 13),
                (12, 10),
                (12, 12),
                (12, 14),
                (13, 11),
                (13, 13),
                (13, 15),
                (14, 12),
                (14, 14),
                (14, 16),
                (15, 13),
                (15, 15),
                (15, 17),
                (16, 14),
                (16, 16),
                (16, 18),
                (17, 15),
                (17, 17),
                (17, 19),
                (18, 16),
                (18, 18),
                (18, 20),
                (19, 17),
                (19, 19),
                (19, 21),
                (20, 18),
                (20, 20),
                (20, 22),
                (21, 19),
                (21, 21),
                (21, 23),
                (22, 20),
                (22, 22),
                (22, 24),
                (23, 21),
                (23, 23),
                (23, 25),
                (24, 22),
                (24, 24),
                (24, 26),
                (25, 23),
                (25, 25),
                (25, 27),
                (26, 24),
                (26, 26),
                (26, 28),
                (27, 25),
                (27, 27),
                (27, 29),
                (28, 26),
                (28, 28),
                (28, 30),
                (29, 27),
                (29, 29),
                (29, 31),
                (30, 28),
                (30, 30),
                (31, 29),
                (31, 31),
            ],
            &[],
        ],
    });
    #[inline]
    fn mass_matrix(
        &self,
        q: &::zeitner::__private::Vector<32>,
        t: ::zeitner::__private::Float,
    ) -> Self::Mass {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let mut m = ::zeitner::__private::Vector::<32>::zeros();
        m[0] = self.m;
        m[1] = self.m;
        m[2] = self.m;
        m[3] = self.m;
        m[4] = self.m;
        m[5] = self.m;
        m[6] = self.m;
        m[7] = self.m;
        m[8] = self.m;
        m[9] = self.m;
        m[10] = self.m;
        m[11] = self.m;
        m[12] = self.m;
        m[13] = self.m;
        m[14] = self.m;
        m[15] = self.m;
        m[16] = self.m;
        m[17] = self.m;
        m[18] = self.m;
        m[19] = self.m;
        m[20] = self.m;
        m[21] = self.m;
        m[22] = self.m;
        m[23] = self.m;
        m[24] = self.m;
        m[25] = self.m;
        m[26] = self.m;
        m[27] = self.m;
        m[28] = self.m;
        m[29] = self.m;
        m[30] = self.m;
        m[31] = self.m;
        ::zeitner::__private::DiagonalMass(m)
    }
    #[inline]
    fn applied_force(
        &self,
        q: &::zeitner::__private::Vector<32>,
        v: &::zeitner::__private::Vector<32>,
        t: ::zeitner::__private::Float,
    ) -> ::zeitner::__private::Vector<32> {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let s0 = -(self.m * self.g);
        let mut f = ::zeitner::__private::Vector::<32>::zeros();
        f[1] = s0;
        f[3] = s0;
        f[5] = s0;
        f[7] = s0;
        f[9] = s0;
        f[11] = s0;
        f[13] = s0;
        f[15] = s0;
        f[17] = s0;
        f[19] = s0;
        f[21] = s0;
        f[23] = s0;
        f[25] = s0;
        f[27] = s0;
        f[29] = s0;
        f[31] = s0;
        f
    }
    #[inline]
    fn constraint_residual(
        &self,
        q: &::zeitner::__private::Vector<32>,
        v: &::zeitner::__private::Vector<32>,
        t: ::zeitner::__private::Float,
    ) -> ::zeitner::__private::Vector<16> {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let s0 = self.l.powi(2);
        let mut g = ::zeitner::__private::Vector::<16>::zeros();
        g[0] = q[0].powi(2) + q[1].powi(2) - s0;
        g[1] = (q[2] - q[0]).powi(2) + (q[3] - q[1]).powi(2) - s0;
        g[2] = (q[4] - q[2]).powi(2) + (q[5] - q[3]).powi(2) - s0;
        g[3] = (q[6] - q[4]).powi(2) + (q[7] - q[5]).powi(2) - s0;
        g[4] = (q[8] - q[6]).powi(2) + (q[9] - q[7]).powi(2) - s0;
        g[5] = (q[10] - q[8]).powi(2) + (q[11] - q[9]).powi(2) - s0;
        g[6] = (q[12] - q[10]).powi(2) + (q[13] - q[11]).powi(2) - s0;
        g[7] = (q[14] - q[12]).powi(2) + (q[15] - q[13]).powi(2) - s0;
        g[8] = (q[16] - q[14]).powi(2) + (q[17] - q[15]).powi(2) - s0;
        g[9] = (q[18] - q[16]).powi(2) + (q[19] - q[17]).powi(2) - s0;
        g[10] = (q[20] - q[18]).powi(2) + (q[21] - q[19]).powi(2) - s0;
        g[11] = (q[22] - q[20]).powi(2) + (q[23] - q[21]).powi(2) - s0;
        g[12] = (q[24] - q[22]).powi(2) + (q[25] - q[23]).powi(2) - s0;
        g[13] = (q[26] - q[24]).powi(2) + (q[27] - q[25]).powi(2) - s0;
        g[14] = (q[28] - q[26]).powi(2) + (q[29] - q[27]).powi(2) - s0;
        g[15] = (q[30] - q[28]).powi(2) + (q[31] - q[29]).powi(2) - s0;
        g
    }
    #[inline]
    fn constraint_jacobian(
        &self,
        q: &::zeitner::__private::Vector<32>,
        v: &::zeitner::__private::Vector<32>,
        t: ::zeitner::__private::Float,
    ) -> ::zeitner::__private::Matrix<16, 32> {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let s0 = 2.0 * (q[2] - q[0]);
        let s1 = 2.0 * (q[3] - q[1]);
        let s2 = 2.0 * (q[4] - q[2]);
        let s3 = 2.0 * (q[5] - q[3]);
        let s4 = 2.0 * (q[6] - q[4]);
        let s5 = 2.0 * (q[7] - q[5]);
        let s6 = 2.0 * (q[8] - q[6]);
        let s7 = 2.0 * (q[9] - q[7]);
        let s8 = 2.0 * (q[10] - q[8]);
        let s9 = 2.0 * (q[11] - q[9]);
        let s10 = 2.0 * (q[12] - q[10]);
        let s11 = 2.0 * (q[13] - q[11]);
        let s12 = 2.0 * (q[14] - q[12]);
        let s13 = 2.0 * (q[15] - q[13]);
        let s14 = 2.0 * (q[16] - q[14]);
        let s15 = 2.0 * (q[17] - q[15]);
        let s16 = 2.0 * (q[18] - q[16]);
        let s17 = 2.0 * (q[19] - q[17]);
        let s18 = 2.0 * (q[20] - q[18]);
        let s19 = 2.0 * (q[21] - q[19]);
        let s20 = 2.0 * (q[22] - q[20]);
        let s21 = 2.0 * (q[23] - q[21]);
        let s22 = 2.0 * (q[24] - q[22]);
        let s23 = 2.0 * (q[25] - q[23]);
        let s24 = 2.0 * (q[26] - q[24]);
        let s25 = 2.0 * (q[27] - q[25]);
        let s26 = 2.0 * (q[28] - q[26]);
        let s27 = 2.0 * (q[29] - q[27]);
        let s28 = 2.0 * (q[30] - q[28]);
        let s29 = 2.0 * (q[31] - q[29]);
        let mut g = ::zeitner::__private::Matrix::<16, 32>::zeros();
        g[(0, 0)] = 2.0 * q[0];
        g[(0, 1)] = 2.0 * q[1];
        g[(1, 0)] = -s0;
        g[(1, 1)] = -s1;
        g[(1, 2)] = s0;
        g[(1, 3)] = s1;
        g[(2, 2)] = -s2;
        g[(2, 3)] = -s3;
        g[(2, 4)] = s2;
        g[(2, 5)] = s3;
        g[(3, 4)] = -s4;
        g[(3, 5)] = -s5;
        g[(3, 6)] = s4;
        g[(3, 7)] = s5;
        g[(4, 6)] = -s6;
        g[(4, 7)] = -s7;
        g[(4, 8)] = s6;
        g[(4, 9)] = s7;
        g[(5, 8)] = -s8;
        g[(5, 9)] = -s9;
        g[(5, 10)] = s8;
        g[(5, 11)] = s9;
        g[(6, 10)] = -s10;
        g[(6, 11)] = -s11;
        g[(6, 12)] = s10;
        g[(6, 13)] = s11;
        g[(7, 12)] = -s12;
        g[(7, 13)] = -s13;
        g[(7, 14)] = s12;
        g[(7, 15)] = s13;
        g[(8, 14)] = -s14;
        g[(8, 15)] = -s15;
        g[(8, 16)] = s14;
        g[(8, 17)] = s15;
        g[(9, 16)] = -s16;
        g[(9, 17)] = -s17;
        g[(9, 18)] = s16;
        g[(9, 19)] = s17;
        g[(10, 18)] = -s18;
        g[(10, 19)] = -s19;
        g[(10, 20)] = s18;
        g[(10, 21)] = s19;
        g[(11, 20)] = -s20;
        g[(11, 21)] = -s21;
        g[(11, 22)] = s20;
        g[(11, 23)] = s21;
        g[(12, 22)] = -s22;
        g[(12, 23)] = -s23;
        g[(12, 24)] = s22;
        g[(12, 25)] = s23;
        g[(13, 24)] = -s24;
        g[(13, 25)] = -s25;
        g[(13, 26)] = s24;
        g[(13, 27)] = s25;
        g[(14, 26)] = -s26;
        g[(14, 27)] = -s27;
        g[(14, 28)] = s26;
        g[(14, 29)] = s27;
        g[(15, 28)] = -s28;
        g[(15, 29)] = -s29;
        g[(15, 30)] = s28;
        g[(15, 31)] = s29;
        g
    }
    #[inline]
    fn constraint_rate(
        &self,
        q: &::zeitner::__private::Vector<32>,
        v: &::zeitner::__private::Vector<32>,
        t: ::zeitner::__private::Float,
    ) -> ::zeitner::__private::Vector<16> {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let s0 = 2.0 * (q[2] - q[0]);
        let s1 = 2.0 * (q[3] - q[1]);
        let s2 = 2.0 * (q[4] - q[2]);
        let s3 = 2.0 * (q[5] - q[3]);
        let s4 = 2.0 * (q[6] - q[4]);
        let s5 = 2.0 * (q[7] - q[5]);
        let s6 = 2.0 * (q[8] - q[6]);
        let s7 = 2.0 * (q[9] - q[7]);
        let s8 = 2.0 * (q[10] - q[8]);
        let s9 = 2.0 * (q[11] - q[9]);
        let s10 = 2.0 * (q[12] - q[10]);
        let s11 = 2.0 * (q[13] - q[11]);
        let s12 = 2.0 * (q[14] - q[12]);
        let s13 = 2.0 * (q[15] - q[13]);
        let s14 = 2.0 * (q[16] - q[14]);
        let s15 = 2.0 * (q[17] - q[15]);
        let s16 = 2.0 * (q[18] - q[16]);
        let s17 = 2.0 * (q[19] - q[17]);
        let s18 = 2.0 * (q[20] - q[18]);
        let s19 = 2.0 * (q[21] - q[19]);
        let s20 = 2.0 * (q[22] - q[20]);
        let s21 = 2.0 * (q[23] - q[21]);
        let s22 = 2.0 * (q[24] - q[22]);
        let s23 = 2.0 * (q[25] - q[23]);
        let s24 = 2.0 * (q[26] - q[24]);
        let s25 = 2.0 * (q[27] - q[25]);
        let s26 = 2.0 * (q[28] - q[26]);
        let s27 = 2.0 * (q[29] - q[27]);
        let s28 = 2.0 * (q[30] - q[28]);
        let s29 = 2.0 * (q[31] - q[29]);
        let mut w = ::zeitner::__private::Vector::<16>::zeros();
        w[0] = 2.0 * q[0] * v[0] + 2.0 * q[1] * v[1];
        w[1] = -(s0 * v[0]) - s1 * v[1] + s0 * v[2] + s1 * v[3];
        w[2] = -(s2 * v[2]) - s3 * v[3] + s2 * v[4] + s3 * v[5];
        w[3] = -(s4 * v[4]) - s5 * v[5] + s4 * v[6] + s5 * v[7];
        w[4] = -(s6 * v[6]) - s7 * v[7] + s6 * v[8] + s7 * v[9];
        w[5] = -(s8 * v[8]) - s9 * v[9] + s8 * v[10] + s9 * v[11];
        w[6] = -(s10 * v[10]) - s11 * v[11] + s10 * v[12] + s11 * v[13];
        w[7] = -(s12 * v[12]) - s13 * v[13] + s12 * v[14] + s13 * v[15];
        w[8] = -(s14 * v[14]) - s15 * v[15] + s14 * v[16] + s15 * v[17];
        w[9] = -(s16 * v[16]) - s17 * v[17] + s16 * v[18] + s17 * v[19];
        w[10] = -(s18 * v[18]) - s19 * v[19] + s18 * v[20] + s19 * v[21];
        w[11] = -(s20 * v[20]) - s21 * v[21] + s20 * v[22] + s21 * v[23];
        w[12] = -(s22 * v[22]) - s23 * v[23] + s22 * v[24] + s23 * v[25];
        w[13] = -(s24 * v[24]) - s25 * v[25] + s24 * v[26] + s25 * v[27];
        w[14] = -(s26 * v[26]) - s27 * v[27] + s26 * v[28] + s27 * v[29];
        w[15] = -(s28 * v[28]) - s29 * v[29] + s28 * v[30] + s29 * v[31];
        w
    }
    #[inline]
    fn constraint_acceleration_bias(
        &self,
        q: &::zeitner::__private::Vector<32>,
        v: &::zeitner::__private::Vector<32>,
        t: ::zeitner::__private::Float,
    ) -> ::zeitner::__private::Vector<16> {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let s0 = 2.0 * v[0];
        let s1 = 2.0 * v[1];
        let s2 = -2.0 * v[2];
        let s3 = -2.0 * v[3];
        let s4 = 2.0 * v[2];
        let s5 = 2.0 * v[3];
        let s6 = -2.0 * v[4];
        let s7 = -2.0 * v[5];
        let s8 = 2.0 * v[4];
        let s9 = 2.0 * v[5];
        let s10 = -2.0 * v[6];
        let s11 = -2.0 * v[7];
        let s12 = 2.0 * v[6];
        let s13 = 2.0 * v[7];
        let s14 = -2.0 * v[8];
        let s15 = -2.0 * v[9];
        let s16 = 2.0 * v[8];
        let s17 = 2.0 * v[9];
        let s18 = -2.0 * v[10];
        let s19 = -2.0 * v[11];
        let s20 = 2.0 * v[10];
        let s21 = 2.0 * v[11];
        let s22 = -2.0 * v[12];
        let s23 = -2.0 * v[13];
        let s24 = 2.0 * v[12];
        let s25 = 2.0 * v[13];
        let s26 = -2.0 * v[14];
        let s27 = -2.0 * v[15];
        let s28 = 2.0 * v[14];
        let s29 = 2.0 * v[15];
        let s30 = -2.0 * v[16];
        let s31 = -2.0 * v[17];
        let s32 = 2.0 * v[16];
        let s33 = 2.0 * v[17];
        let s34 = -2.0 * v[18];
        let s35 = -2.0 * v[19];
        let s36 = 2.0 * v[18];
        let s37 = 2.0 * v[19];
        let s38 = -2.0 * v[20];
        let s39 = -2.0 * v[21];
        let s40 = 2.0 * v[20];
        let s41 = 2.0 * v[21];
        let s42 = -2.0 * v[22];
        let s43 = -2.0 * v[23];
        let s44 = 2.0 * v[22];
        let s45 = 2.0 * v[23];
        let s46 = -2.0 * v[24];
        let s47 = -2.0 * v[25];
        let s48 = 2.0 * v[24];
        let s49 = 2.0 * v[25];
        let s50 = -2.0 * v[26];
        let s51 = -2.0 * v[27];
        let s52 = 2.0 * v[26];
        let s53 = 2.0 * v[27];
        let s54 = -2.0 * v[28];
        let s55 = -2.0 * v[29];
        let s56 = 2.0 * v[28];
        let s57 = 2.0 * v[29];
        let mut b = ::zeitner::__private::Vector::<16>::zeros();
        b[0] = v[0] * s0 + v[1] * s1;
        b[1] = v[0] * (s2 - -2.0 * v[0]) + v[1] * (s3 - -2.0 * v[1]) + v[2] * (s4 - s0)
            + v[3] * (s5 - s1);
        b[2] = v[2] * (s6 - s2) + v[3] * (s7 - s3) + v[4] * (s8 - s4) + v[5] * (s9 - s5);
        b[3] = v[4] * (s10 - s6) + v[5] * (s11 - s7) + v[6] * (s12 - s8)
            + v[7] * (s13 - s9);
        b[4] = v[6] * (s14 - s10) + v[7] * (s15 - s11) + v[8] * (s16 - s12)
            + v[9] * (s17 - s13);
        b[5] = v[8] * (s18 - s14) + v[9] * (s19 - s15) + v[10] * (s20 - s16)
            + v[11] * (s21 - s17);
        b[6] = v[10] * (s22 - s18) + v[11] * (s23 - s19) + v[12] * (s24 - s20)
            + v[13] * (s25 - s21);
        b[7] = v[12] * (s26 - s22) + v[13] * (s27 - s23) + v[14] * (s28 - s24)
            + v[15] * (s29 - s25);
        b[8] = v[14] * (s30 - s26) + v[15] * (s31 - s27) + v[16] * (s32 - s28)
            + v[17] * (s33 - s29);
        b[9] = v[16] * (s34 - s30) + v[17] * (s35 - s31) + v[18] * (s36 - s32)
            + v[19] * (s37 - s33);
        b[10] = v[18] * (s38 - s34) + v[19] * (s39 - s35) + v[20] * (s40 - s36)
            + v[21] * (s41 - s37);
        b[11] = v[20] * (s42 - s38) + v[21] * (s43 - s39) + v[22] * (s44 - s40)
            + v[23] * (s45 - s41);
        b[12] = v[22] * (s46 - s42) + v[23] * (s47 - s43) + v[24] * (s48 - s44)
            + v[25] * (s49 - s45);
        b[13] = v[24] * (s50 - s46) + v[25] * (s51 - s47) + v[26] * (s52 - s48)
            + v[27] * (s53 - s49);
        b[14] = v[26] * (s54 - s50) + v[27] * (s55 - s51) + v[28] * (s56 - s52)
            + v[29] * (s57 - s53);
        b[15] = v[28] * (-2.0 * v[30] - s54) + v[29] * (-2.0 * v[31] - s55)
            + v[30] * (2.0 * v[30] - s56) + v[31] * (2.0 * v[31] - s57);
        b
    }
    #[inline]
    fn stage(
        &self,
        q: &::zeitner::__private::Vector<32>,
        v: &::zeitner::__private::Vector<32>,
        t: ::zeitner::__private::Float,
    ) -> (
        Self::Mass,
        ::zeitner::__private::Vector<32>,
        ::zeitner::__private::Matrix<16, 32>,
        ::zeitner::__private::Vector<16>,
    ) {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let s0 = -(self.m * self.g);
        let s1 = 2.0 * (q[2] - q[0]);
        let s2 = 2.0 * (q[3] - q[1]);
        let s3 = 2.0 * (q[4] - q[2]);
        let s4 = 2.0 * (q[5] - q[3]);
        let s5 = 2.0 * (q[6] - q[4]);
        let s6 = 2.0 * (q[7] - q[5]);
        let s7 = 2.0 * (q[8] - q[6]);
        let s8 = 2.0 * (q[9] - q[7]);
        let s9 = 2.0 * (q[10] - q[8]);
        let s10 = 2.0 * (q[11] - q[9]);
        let s11 = 2.0 * (q[12] - q[10]);
        let s12 = 2.0 * (q[13] - q[11]);
        let s13 = 2.0 * (q[14] - q[12]);
        let s14 = 2.0 * (q[15] - q[13]);
        let s15 = 2.0 * (q[16] - q[14]);
        let s16 = 2.0 * (q[17] - q[15]);
        let s17 = 2.0 * (q[18] - q[16]);
        let s18 = 2.0 * (q[19] - q[17]);
        let s19 = 2.0 * (q[20] - q[18]);
        let s20 = 2.0 * (q[21] - q[19]);
        let s21 = 2.0 * (q[22] - q[20]);
        let s22 = 2.0 * (q[23] - q[21]);
        let s23 = 2.0 * (q[24] - q[22]);
        let s24 = 2.0 * (q[25] - q[23]);
        let s25 = 2.0 * (q[26] - q[24]);
        let s26 = 2.0 * (q[27] - q[25]);
        let s27 = 2.0 * (q[28] - q[26]);
        let s28 = 2.0 * (q[29] - q[27]);
        let s29 = 2.0 * (q[30] - q[28]);
        let s30 = 2.0 * (q[31] - q[29]);
        let s31 = 2.0 * v[0];
        let s32 = 2.0 * v[1];
        let s33 = -2.0 * v[2];
        let s34 = -2.0 * v[3];
        let s35 = 2.0 * v[2];
        let s36 = 2.0 * v[3];
        let s37 = -2.0 * v[4];
        let s38 = -2.0 * v[5];
        let s39 = 2.0 * v[4];
        let s40 = 2.0 * v[5];
        let s41 = -2.0 * v[6];
        let s42 = -2.0 * v[7];
        let s43 = 2.0 * v[6];
        let s44 = 2.0 * v[7];
        let s45 = -2.0 * v[8];
        let s46 = -2.0 * v[9];
        let s47 = 2.0 * v[8];
        let s48 = 2.0 * v[9];
        let s49 = -2.0 * v[10];
        let s50 = -2.0 * v[11];
        let s51 = 2.0 * v[10];
        let s52 = 2.0 * v[11];
        let s53 = -2.0 * v[12];
        let s54 = -2.0 * v[13];
        let s55 = 2.0 * v[12];
        let s56 = 2.0 * v[13];
        let s57 = -2.0 * v[14];
        let s58 = -2.0 * v[15];
        let s59 = 2.0 * v[14];
        let s60 = 2.0 * v[15];
        let s61 = -2.0 * v[16];
        let s62 = -2.0 * v[17];
        let s63 = 2.0 * v[16];
        let s64 = 2.0 * v[17];
        let s65 = -2.0 * v[18];
        let s66 = -2.0 * v[19];
        let s67 = 2.0 * v[18];
        let s68 = 2.0 * v[19];
        let s69 = -2.0 * v[20];
        let s70 = -2.0 * v[21];
        let s71 = 2.0 * v[20];
        let s72 = 2.0 * v[21];
        let s73 = -2.0 * v[22];
        let s74 = -2.0 * v[23];
        let s75 = 2.0 * v[22];
        let s76 = 2.0 * v[23];
        let s77 = -2.0 * v[24];
        let s78 = -2.0 * v[25];
        let s79 = 2.0 * v[24];
        let s80 = 2.0 * v[25];
        let s81 = -2.0 * v[26];
        let s82 = -2.0 * v[27];
        let s83 = 2.0 * v[26];
        let s84 = 2.0 * v[27];
        let s85 = -2.0 * v[28];
        let s86 = -2.0 * v[29];
        let s87 = 2.0 * v[28];
        let s88 = 2.0 * v[29];
        let mut m = ::zeitner::__private::Vector::<32>::zeros();
        let mut f = ::zeitner::__private::Vector::<32>::zeros();
        let mut g = ::zeitner::__private::Matrix::<16, 32>::zeros();
        let mut b = ::zeitner::__private::Vector::<16>::zeros();
        m[0] = self.m;
        m[1] = self.m;
        m[2] = self.m;
        m[3] = self.m;
        m[4] = self.m;
        m[5] = self.m;
        m[6] = self.m;
        m[7] = self.m;
        m[8] = self.m;
        m[9] = self.m;
        m[10] = self.m;
        m[11] = self.m;
        m[12] = self.m;
        m[13] = self.m;
        m[14] = self.m;
        m[15] = self.m;
        m[16] = self.m;
        m[17] = self.m;
        m[18] = self.m;
        m[19] = self.m;
        m[20] = self.m;
        m[21] = self.m;
        m[22] = self.m;
        m[23] = self.m;
        m[24] = self.m;
        m[25] = self.m;
        m[26] = self.m;
        m[27] = self.m;
        m[28] = self.m;
        m[29] = self.m;
        m[30] = self.m;
        m[31] = self.m;
        f[1] = s0;
        f[3] = s0;
        f[5] = s0;
        f[7] = s0;
        f[9] = s0;
        f[11] = s0;
        f[13] = s0;
        f[15] = s0;
        f[17] = s0;
        f[19] = s0;
        f[21] = s0;
        f[23] = s0;
        f[25] = s0;
        f[27] = s0;
        f[29] = s0;
        f[31] = s0;
        g[(0, 0)] = 2.0 * q[0];
        g[(0, 1)] = 2.0 * q[1];
        g[(1, 0)] = -s1;
        g[(1, 1)] = -s2;
        g[(1, 2)] = s1;
        g[(1, 3)] = s2;
        g[(2, 2)] = -s3;
        g[(2, 3)] = -s4;
        g[(2, 4)] = s3;
        g[(2, 5)] = s4;
        g[(3, 4)] = -s5;
        g[(3, 5)] = -s6;
        g[(3, 6)] = s5;
        g[(3, 7)] = s6;
        g[(4, 6)] = -s7;
        g[(4, 7)] = -s8;
        g[(4, 8)] = s7;
        g[(4, 9)] = s8;
        g[(5, 8)] = -s9;
        g[(5, 9)] = -s10;
        g[(5, 10)] = s9;
        g[(5, 11)] = s10;
        g[(6, 10)] = -s11;
        g[(6, 11)] = -s12;
        g[(6, 12)] = s11;
        g[(6, 13)] = s12;
        g[(7, 12)] = -s13;
        g[(7, 13)] = -s14;
        g[(7, 14)] = s13;
        g[(7, 15)] = s14;
        g[(8, 14)] = -s15;
        g[(8, 15)] = -s16;
        g[(8, 16)] = s15;
        g[(8, 17)] = s16;
        g[(9, 16)] = -s17;
        g[(9, 17)] = -s18;
        g[(9, 18)] = s17;
        g[(9, 19)] = s18;
        g[(10, 18)] = -s19;
        g[(10, 19)] = -s20;
        g[(10, 20)] = s19;
        g[(10, 21)] = s20;
        g[(11, 20)] = -s21;
        g[(11, 21)] = -s22;
        g[(11, 22)] = s21;
        g[(11, 23)] = s22;
        g[(12, 22)] = -s23;
        g[(12, 23)] = -s24;
        g[(12, 24)] = s23;
        g[(12, 25)] = s24;
        g[(13, 24)] = -s25;
        g[(13, 25)] = -s26;
        g[(13, 26)] = s25;
        g[(13, 27)] = s26;
        g[(14, 26)] = -s27;
        g[(14, 27)] = -s28;
        g[(14, 28)] = s27;
        g[(14, 29)] = s28;
        g[(15, 28)] = -s29;
        g[(15, 29)] = -s30;
        g[(15, 30)] = s29;
        g[(15, 31)] = s30;
        b[0] = v[0] * s31 + v[1] * s32;
        b[1] = v[0] * (s33 - -2.0 * v[0]) + v[1] * (s34 - -2.0 * v[1])
            + v[2] * (s35 - s31) + v[3] * (s36 - s32);
        b[2] = v[2] * (s37 - s33) + v[3] * (s38 - s34) + v[4] * (s39 - s35)
            + v[5] * (s40 - s36);
        b[3] = v[4] * (s41 - s37) + v[5] * (s42 - s38) + v[6] * (s43 - s39)
            + v[7] * (s44 - s40);
        b[4] = v[6] * (s45 - s41) + v[7] * (s46 - s42) + v[8] * (s47 - s43)
            + v[9] * (s48 - s44);
        b[5] = v[8] * (s49 - s45) + v[9] * (s50 - s46) + v[10] * (s51 - s47)
            + v[11] * (s52 - s48);
        b[6] = v[10] * (s53 - s49) + v[11] * (s54 - s50) + v[12] * (s55 - s51)
            + v[13] * (s56 - s52);
        b[7] = v[12] * (s57 - s53) + v[13] * (s58 - s54) + v[14] * (s59 - s55)
            + v[15] * (s60 - s56);
        b[8] = v[14] * (s61 - s57) + v[15] * (s62 - s58) + v[16] * (s63 - s59)
            + v[17] * (s64 - s60);
        b[9] = v[16] * (s65 - s61) + v[17] * (s66 - s62) + v[18] * (s67 - s63)
            + v[19] * (s68 - s64);
        b[10] = v[18] * (s69 - s65) + v[19] * (s70 - s66) + v[20] * (s71 - s67)
            + v[21] * (s72 - s68);
        b[11] = v[20] * (s73 - s69) + v[21] * (s74 - s70) + v[22] * (s75 - s71)
            + v[23] * (s76 - s72);
        b[12] = v[22] * (s77 - s73) + v[23] * (s78 - s74) + v[24] * (s79 - s75)
            + v[25] * (s80 - s76);
        b[13] = v[24] * (s81 - s77) + v[25] * (s82 - s78) + v[26] * (s83 - s79)
            + v[27] * (s84 - s80);
        b[14] = v[26] * (s85 - s81) + v[27] * (s86 - s82) + v[28] * (s87 - s83)
            + v[29] * (s88 - s84);
        b[15] = v[28] * (-2.0 * v[30] - s85) + v[29] * (-2.0 * v[31] - s86)
            + v[30] * (2.0 * v[30] - s87) + v[31] * (2.0 * v[31] - s88);
        (::zeitner::__private::DiagonalMass(m), f, g, b)
    }
    #[inline]
    fn force_jacobians(
        &self,
        q: &::zeitner::__private::Vector<32>,
        v: &::zeitner::__private::Vector<32>,
        t: ::zeitner::__private::Float,
    ) -> (::zeitner::__private::Matrix<32, 32>, ::zeitner::__private::Matrix<32, 32>) {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let mut dq = ::zeitner::__private::Matrix::<32, 32>::zeros();
        let mut dv = ::zeitner::__private::Matrix::<32, 32>::zeros();
        (dq, dv)
    }
    #[inline]
    fn constraint_force_jacobians(
        &self,
        q: &::zeitner::__private::Vector<32>,
        v: &::zeitner::__private::Vector<32>,
        t: ::zeitner::__private::Float,
        lambda: &::zeitner::__private::Vector<16>,
    ) -> (::zeitner::__private::Matrix<32, 32>, ::zeitner::__private::Matrix<32, 32>) {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let s0 = -2.0 * lambda[1];
        let s1 = 2.0 * lambda[0] - s0;
        let s2 = 2.0 * lambda[1];
        let s3 = -s2;
        let s4 = -2.0 * lambda[2];
        let s5 = s2 - s4;
        let s6 = 2.0 * lambda[2];
        let s7 = -s6;
        let s8 = -2.0 * lambda[3];
        let s9 = s6 - s8;
        let s10 = 2.0 * lambda[3];
        let s11 = -s10;
        let s12 = -2.0 * lambda[4];
        let s13 = s10 - s12;
        let s14 = 2.0 * lambda[4];
        let s15 = -s14;
        let s16 = -2.0 * lambda[5];
        let s17 = s14 - s16;
        let s18 = 2.0 * lambda[5];
        let s19 = -s18;
        let s20 = -2.0 * lambda[6];
        let s21 = s18 - s20;
        let s22 = 2.0 * lambda[6];
        let s23 = -s22;
        let s24 = -2.0 * lambda[7];
        let s25 = s22 - s24;
        let s26 = 2.0 * lambda[7];
        let s27 = -s26;
        let s28 = -2.0 * lambda[8];
        let s29 = s26 - s28;
        let s30 = 2.0 * lambda[8];
        let s31 = -s30;
        let s32 = -2.0 * lambda[9];
        let s33 = s30 - s32;
        let s34 = 2.0 * lambda[9];
        let s35 = -s34;
        let s36 = -2.0 * lambda[10];
        let s37 = s34 - s36;
        let s38 = 2.0 * lambda[10];
        let s39 = -s38;
        let s40 = -2.0 * lambda[11];
        let s41 = s38 - s40;
        let s42 = 2.0 * lambda[11];
        let s43 = -s42;
        let s44 = -2.0 * lambda[12];
        let s45 = s42 - s44;
        let s46 = 2.0 * lambda[12];
        let s47 = -s46;
        let s48 = -2.0 * lambda[13];
        let s49 = s46 - s48;
        let s50 = 2.0 * lambda[13];
        let s51 = -s50;
        let s52 = -2.0 * lambda[14];
        let s53 = s50 - s52;
        let s54 = 2.0 * lambda[14];
        let s55 = -s54;
        let s56 = -2.0 * lambda[15];
        let s57 = s54 - s56;
        let s58 = 2.0 * lambda[15];
        let s59 = -s58;
        let mut dq = ::zeitner::__private::Matrix::<32, 32>::zeros();
        let mut dv = ::zeitner::__private::Matrix::<32, 32>::zeros();
        dq[(0, 0)] = s1;
        dq[(0, 2)] = s3;
        dq[(1, 1)] = s1;
        dq[(1, 3)] = s3;
        dq[(2, 0)] = s0;
        dq[(2, 2)] = s5;
        dq[(2, 4)] = s7;
        dq[(3, 1)] = s0;
        dq[(3, 3)] = s5;
        dq[(3, 5)] = s7;
        dq[(4, 2)] = s4;
        dq[(4, 4)] = s9;
        dq[(4, 6)] = s11;
        dq[(5, 3)] = s4;
        dq[(5, 5)] = s9;
        dq[(5, 7)] = s11;
        dq[(6, 4)] = s8;
        dq[(6, 6)] = s13;
        dq[(6, 8)] = s15;
        dq[(7, 5)] = s8;
        dq[(7, 7)] = s13;
        dq[(7, 9)] = s15;
        dq[(8, 6)] = s12;
        dq[(8, 8)] = s17;
        dq[(8, 10)] = s19;
        dq[(9, 7)] = s12;
        dq[(9, 9)] = s17;
        dq[(9, 11)] = s19;
        dq[(10, 8)] = s16;
        dq[(10, 10)] = s21;
        dq[(10, 12)] = s23;
        dq[(11, 9)] = s16;
        dq[(11, 11)] = s21;
        dq[(11, 13)] = s23;
        dq[(12, 10)] = s20;
        dq[(12, 12)] = s25;
        dq[(12, 14)] = s27;
        dq[(13, 11)] = s20;
        dq[(13, 13)] = s25;
        dq[(13, 15)] = s27;
        dq[(14, 12)] = s24;
        dq[(14, 14)] = s29;
        dq[(14, 16)] = s31;
        dq[(15, 13)] = s24;
        dq[(15, 15)] = s29;
        dq[(15, 17)] = s31;
        dq[(16, 14)] = s28;
        dq[(16, 16)] = s33;
        dq[(16, 18)] = s35;
        dq[(17, 15)] = s28;
        dq[(17, 17)] = s33;
        dq[(17, 19)] = s35;
        dq[(18, 16)] = s32;
        dq[(18, 18)] = s37;
        dq[(18, 20)] = s39;
        dq[(19, 17)] = s32;
        dq[(19, 19)] = s37;
        dq[(19, 21)] = s39;
        dq[(20, 18)] = s36;
        dq[(20, 20)] = s41;
        dq[(20, 22)] = s43;
        dq[(21, 19)] = s36;
        dq[(21, 21)] = s41;
        dq[(21, 23)] = s43;
        dq[(22, 20)] = s40;
        dq[(22, 22)] = s45;
        dq[(22, 24)] = s47;
        dq[(23, 21)] = s40;
        dq[(23, 23)] = s45;
        dq[(23, 25)] = s47;
        dq[(24, 22)] = s44;
        dq[(24, 24)] = s49;
        dq[(24, 26)] = s51;
        dq[(25, 23)] = s44;
        dq[(25, 25)] = s49;
        dq[(25, 27)] = s51;
        dq[(26, 24)] = s48;
        dq[(26, 26)] = s53;
        dq[(26, 28)] = s55;
        dq[(27, 25)] = s48;
        dq[(27, 27)] = s53;
        dq[(27, 29)] = s55;
        dq[(28, 26)] = s52;
        dq[(28, 28)] = s57;
        dq[(28, 30)] = s59;
        dq[(29, 27)] = s52;
        dq[(29, 29)] = s57;
        dq[(29, 31)] = s59;
        dq[(30, 28)] = s56;
        dq[(30, 30)] = s58;
        dq[(31, 29)] = s56;
        dq[(31, 31)] = s58;
        (dq, dv)
    }
    #[inline]
    fn constraint_jacobian_nonzeros(
        &self,
        q: &::zeitner::__private::Vector<32>,
        v: &::zeitner::__private::Vector<32>,
        t: ::zeitner::__private::Float,
        values: &mut [::zeitner::__private::Float],
    ) {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let s0 = 2.0 * (q[2] - q[0]);
        let s1 = 2.0 * (q[3] - q[1]);
        let s2 = 2.0 * (q[4] - q[2]);
        let s3 = 2.0 * (q[5] - q[3]);
        let s4 = 2.0 * (q[6] - q[4]);
        let s5 = 2.0 * (q[7] - q[5]);
        let s6 = 2.0 * (q[8] - q[6]);
        let s7 = 2.0 * (q[9] - q[7]);
        let s8 = 2.0 * (q[10] - q[8]);
        let s9 = 2.0 * (q[11] - q[9]);
        let s10 = 2.0 * (q[12] - q[10]);
        let s11 = 2.0 * (q[13] - q[11]);
        let s12 = 2.0 * (q[14] - q[12]);
        let s13 = 2.0 * (q[15] - q[13]);
        let s14 = 2.0 * (q[16] - q[14]);
        let s15 = 2.0 * (q[17] - q[15]);
        let s16 = 2.0 * (q[18] - q[16]);
        let s17 = 2.0 * (q[19] - q[17]);
        let s18 = 2.0 * (q[20] - q[18]);
        let s19 = 2.0 * (q[21] - q[19]);
        let s20 = 2.0 * (q[22] - q[20]);
        let s21 = 2.0 * (q[23] - q[21]);
        let s22 = 2.0 * (q[24] - q[22]);
        let s23 = 2.0 * (q[25] - q[23]);
        let s24 = 2.0 * (q[26] - q[24]);
        let s25 = 2.0 * (q[27] - q[25]);
        let s26 = 2.0 * (q[28] - q[26]);
        let s27 = 2.0 * (q[29] - q[27]);
        let s28 = 2.0 * (q[30] - q[28]);
        let s29 = 2.0 * (q[31] - q[29]);
        values[0] = 2.0 * q[0];
        values[1] = 2.0 * q[1];
        values[2] = -s0;
        values[3] = -s1;
        values[4] = s0;
        values[5] = s1;
        values[6] = -s2;
        values[7] = -s3;
        values[8] = s2;
        values[9] = s3;
        values[10] = -s4;
        values[11] = -s5;
        values[12] = s4;
        values[13] = s5;
        values[14] = -s6;
        values[15] = -s7;
        values[16] = s6;
        values[17] = s7;
        values[18] = -s8;
        values[19] = -s9;
        values[20] = s8;
        values[21] = s9;
        values[22] = -s10;
        values[23] = -s11;
        values[24] = s10;
        values[25] = s11;
        values[26] = -s12;
        values[27] = -s13;
        values[28] = s12;
        values[29] = s13;
        values[30] = -s14;
        values[31] = -s15;
        values[32] = s14;
        values[33] = s15;
        values[34] = -s16;
        values[35] = -s17;
        values[36] = s16;
        values[37] = s17;
        values[38] = -s18;
        values[39] = -s19;
        values[40] = s18;
        values[41] = s19;
        values[42] = -s20;
        values[43] = -s21;
        values[44] = s20;
        values[45] = s21;
        values[46] = -s22;
        values[47] = -s23;
        values[48] = s22;
        values[49] = s23;
        values[50] = -s24;
        values[51] = -s25;
        values[52] = s24;
        values[53] = s25;
        values[54] = -s26;
        values[55] = -s27;
        values[56] = s26;
        values[57] = s27;
        values[58] = -s28;
        values[59] = -s29;
        values[60] = s28;
        values[61] = s29;
    }
    #[inline]
    fn force_jacobian_nonzeros(
        &self,
        q: &::zeitner::__private::Vector<32>,
        v: &::zeitner::__private::Vector<32>,
        t: ::zeitner::__private::Float,
        values: &mut [::zeitner::__private::Float],
    ) {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
    }
    #[inline]
    fn constraint_force_jacobian_nonzeros(
        &self,
        q: &::zeitner::__private::Vector<32>,
        v: &::zeitner::__private::Vector<32>,
        t: ::zeitner::__private::Float,
        lambda: &::zeitner::__private::Vector<16>,
        values: &mut [::zeitner::__private::Float],
    ) {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let s0 = -2.0 * lambda[1];
        let s1 = 2.0 * lambda[0] - s0;
        let s2 = 2.0 * lambda[1];
        let s3 = -s2;
        let s4 = -2.0 * lambda[2];
        let s5 = s2 - s4;
        let s6 = 2.0 * lambda[2];
        let s7 = -s6;
        let s8 = -2.0 * lambda[3];
        let s9 = s6 - s8;
        let s10 = 2.0 * lambda[3];
        let s11 = -s10;
        let s12 = -2.0 * lambda[4];
        let s13 = s10 - s12;
        let s14 = 2.0 * lambda[4];
        let s15 = -s14;
        let s16 = -2.0 * lambda[5];
        let s17 = s14 - s16;
        let s18 = 2.0 * lambda[5];
        let s19 = -s18;
        let s20 = -2.0 * lambda[6];
        let s21 = s18 - s20;
        let s22 = 2.0 * lambda[6];
        let s23 = -s22;
        let s24 = -2.0 * lambda[7];
        let s25 = s22 - s24;
        let s26 = 2.0 * lambda[7];
        let s27 = -s26;
        let s28 = -2.0 * lambda[8];
        let s29 = s26 - s28;
        let s30 = 2.0 * lambda[8];
        let s31 = -s30;
        let s32 = -2.0 * lambda[9];
        let s33 = s30 - s32;
        let s34 = 2.0 * lambda[9];
        let s35 = -s34;
        let s36 = -2.0 * lambda[10];
        let s37 = s34 - s36;
        let s38 = 2.0 * lambda[10];
        let s39 = -s38;
        let s40 = -2.0 * lambda[11];
        let s41 = s38 - s40;
        let s42 = 2.0 * lambda[11];
        let s43 = -s42;
        let s44 = -2.0 * lambda[12];
        let s45 = s42 - s44;
        let s46 = 2.0 * lambda[12];
        let s47 = -s46;
        let s48 = -2.0 * lambda[13];
        let s49 = s46 - s48;
        let s50 = 2.0 * lambda[13];
        let s51 = -s50;
        let s52 = -2.0 * lambda[14];
        let s53 = s50 - s52;
        let s54 = 2.0 * lambda[14];
        let s55 = -s54;
        let s56 = -2.0 * lambda[15];
        let s57 = s54 - s56;
        let s58 = 2.0 * lambda[15];
        let s59 = -s58;
        values[0] = s1;
        values[1] = s3;
        values[2] = s1;
        values[3] = s3;
        values[4] = s0;
        values[5] = s5;
        values[6] = s7;
        values[7] = s0;
        values[8] = s5;
        values[9] = s7;
        values[10] = s4;
        values[11] = s9;
        values[12] = s11;
        values[13] = s4;
        values[14] = s9;
        values[15] = s11;
        values[16] = s8;
        values[17] = s13;
        values[18] = s15;
        values[19] = s8;
        values[20] = s13;
        values[21] = s15;
        values[22] = s12;
        values[23] = s17;
        values[24] = s19;
        values[25] = s12;
        values[26] = s17;
        values[27] = s19;
        values[28] = s16;
        values[29] = s21;
        values[30] = s23;
        values[31] = s16;
        values[32] = s21;
        values[33] = s23;
        values[34] = s20;
        values[35] = s25;
        values[36] = s27;
        values[37] = s20;
        values[38] = s25;
        values[39] = s27;
        values[40] = s24;
        values[41] = s29;
        values[42] = s31;
        values[43] = s24;
        values[44] = s29;
        values[45] = s31;
        values[46] = s28;
        values[47] = s33;
        values[48] = s35;
        values[49] = s28;
        values[50] = s33;
        values[51] = s35;
        values[52] = s32;
        values[53] = s37;
        values[54] = s39;
        values[55] = s32;
        values[56] = s37;
        values[57] = s39;
        values[58] = s36;
        values[59] = s41;
        values[60] = s43;
        values[61] = s36;
        values[62] = s41;
        values[63] = s43;
        values[64] = s40;
        values[65] = s45;
        values[66] = s47;
        values[67] = s40;
        values[68] = s45;
        values[69] = s47;
        values[70] = s44;
        values[71] = s49;
        values[72] = s51;
        values[73] = s44;
        values[74] = s49;
        values[75] = s51;
        values[76] = s48;
        values[77] = s53;
        values[78] = s55;
        values[79] = s48;
        values[80] = s53;
        values[81] = s55;
        values[82] = s52;
        values[83] = s57;
        values[84] = s59;
        values[85] = s52;
        values[86] = s57;
        values[87] = s59;
        values[88] = s56;
        values[89] = s58;
        values[90] = s56;
        values[91] = s58;
    }
}
#[allow(dead_code)]
impl Chain100 {
    const LINKS: usize = 100;
    fn mass(&self) -> [Float; 2 * Self::LINKS] {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        [self.m; 2 * Self::LINKS]
    }
    fn force(&self) -> [Float; 2 * Self::LINKS] {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let mut f = [0.0; 2 * Self::LINKS];
        for i in 0..Self::LINKS {
            f[2 * i + 1] = -self.m * self.g;
        }
        f
    }
    fn constraints(&self, q: [Float; 2 * Self::LINKS]) -> [Float; Self::LINKS] {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let mut g = [0.0; Self::LINKS];
        g[0] = q[0] * q[0] + q[1] * q[1] - self.l * self.l;
        for i in 1..Self::LINKS {
            g[i] = (q[2 * i] - q[2 * i - 2]).powi(2)
                + (q[2 * i + 1] - q[2 * i - 1]).powi(2) - self.l * self.l;
        }
        g
    }
}
#[allow(unused_variables, unused_mut, clippy::all)]
impl ::zeitner::__private::ConstrainedSystem<200, 100> for Chain100 {
    const POSITION_CONSTRAINTS: usize = 100;
    const MASS_IS_CONSTANT: bool = true;
    const DYNAMICS_DEPEND_ON_VELOCITY: bool = false;
    const SUMMARY: ::zeitner::__private::SceneSummary = ::zeitner::__private::SceneSummary {
        coordinates: 200,
        position_constraints: 100,
        velocity_constraints: 0,
        mass: ::zeitner::__private::MassKind::ConstantDiagonal,
        time_dependent: false,
        functions: &[
            ::zeitner::__private::FunctionSummary {
                name: "mass_matrix",
                blocks: &[
                    ::zeitner::__private::BlockSummary {
                        name: "m",
                        rows: 200,
                        cols: 1,
                        nonzeros: &[
                            (0, 0),
                            (1, 0),
                            (2, 0),
                            (3, 0),
                            (4, 0),
                            (5, 0),
                            (6, 0),
                            (7, 0),
                            (8, 0),
                            (9, 0),
                            (10, 0),
                            (11, 0),
                            (12, 0),
                            (13, 0),
                            (14, 0),
                            (15, 0),
                            (16, 0),
                            (17, 0),
                            (18, 0),
                            (19, 0),
                            (20, 0),
                            (21, 0),
                            (22, 0),
                            (23, 0),
                            (24, 0),
                            (25, 0),
                            (26, 0),
                            (27, 0),
                            (28, 0),
                            (29, 0),
                            (30, 0),
                            (31, 0),
                            (32, 0),
                            (33, 0),
                            (34, 0),
                            (35, 0),
                            (36, 0),
                            (37, 0),
                            (38, 0),
                            (39, 0),
                            (40, 0),
                            (41, 0),
                            (42, 0),
                            (43, 0),
                            (44, 0),
                            (45, 0),
                            (46, 0),
                            (47, 0),
                            (48, 0),
                            (49, 0),
                            (50, 0),
                            (51, 0),
                            (52, 0),
                            (53, 0),
                            (54, 0),
                            (55, 0),
                            (56, 0),
                            (57, 0),
                            (58, 0),
                            (59, 0),
                            (60, 0),
                            (61, 0),
                            (62, 0),
                            (63, 0),
                            (64, 0),
                            (65, 0),
                            (66, 0),
                            (67, 0),
                            (68, 0),
                            (69, 0),
                            (70, 0),
                            (71, 0),
                            (72, 0),
                            (73, 0),
                            (74, 0),
                            (75, 0),
                            (76, 0),
                            (77, 0),
                            (78, 0),
                            (79, 0),
                            (80, 0),
                            (81, 0),
                            (82, 0),
                            (83, 0),
                            (84, 0),
                            (85, 0),
                            (86, 0),
                            (87, 0),
                            (88, 0),
                            (89, 0),
                            (90, 0),
                            (91, 0),
                            (92, 0),
                            (93, 0),
                            (94, 0),
                            (95, 0),
                            (96, 0),
                            (97, 0),
                            (98, 0),
                            (99, 0),
                            (100, 0),
                            (101, 0),
                            (102, 0),
                            (103, 0),
                            (104, 0),
                            (105, 0),
                            (106, 0),
                            (107, 0),
                            (108, 0),
                            (109, 0),
                            (110, 0),
                            (111, 0),
                            (112, 0),
                            (113, 0),
                            (114, 0),
                            (115, 0),
                            (116, 0),
                            (117, 0),
                            (118, 0),
                            (119, 0),
                            (120, 0),
                            (121, 0),
                            (122, 0),
                            (123, 0),
                            (124, 0),
                            (125, 0),
                            (126, 0),
                            (127, 0),
                            (128, 0),
                            (129, 0),
                            (130, 0),
                            (131, 0),
                            (132, 0),
                            (133, 0),
                            (134, 0),
                            (135, 0),
                            (136, 0),
                            (137, 0),
                            (138, 0),
                            (139, 0),
                            (140, 0),
                            (141, 0),
                            (142, 0),
                            (143, 0),
                            (144, 0),
                            (145, 0),
                            (146, 0),
                            (147, 0),
                            (148, 0),
                            (149, 0),
                            (150, 0),
                            (151, 0),
                            (152, 0),
                            (153, 0),
                            (154, 0),
                            (155, 0),
                            (156, 0),
                            (157, 0),
                            (158, 0),
                            (159, 0),
                            (160, 0),
                            (161, 0),
                            (162, 0),
                            (163, 0),
                            (164, 0),
                            (165, 0),
                            (166, 0),
                            (167, 0),
                            (168, 0),
                            (169, 0),
                            (170, 0),
                            (171, 0),
                            (172, 0),
                            (173, 0),
                            (174, 0),
                            (175, 0),
                            (176, 0),
                            (177, 0),
                            (178, 0),
                            (179, 0),
                            (180, 0),
                            (181, 0),
                            (182, 0),
                            (183, 0),
                            (184, 0),
                            (185, 0),
                            (186, 0),
                            (187, 0),
                            (188, 0),
                            (189, 0),
                            (190, 0),
                            (191, 0),
                            (192, 0),
                            (193, 0),
                            (194, 0),
                            (195, 0),
                            (196, 0),
                            (197, 0),
                            (198, 0),
                            (199, 0),
                        ],
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
                        rows: 200,
                        cols: 1,
                        nonzeros: &[
                            (1, 0),
                            (3, 0),
                            (5, 0),
                            (7, 0),
                            (9, 0),
                            (11, 0),
                            (13, 0),
                            (15, 0),
                            (17, 0),
                            (19, 0),
                            (21, 0),
                            (23, 0),
                            (25, 0),
                            (27, 0),
                            (29, 0),
                            (31, 0),
                            (33, 0),
                            (35, 0),
                            (37, 0),
                            (39, 0),
                            (41, 0),
                            (43, 0),
                            (45, 0),
                            (47, 0),
                            (49, 0),
                            (51, 0),
                            (53, 0),
                            (55, 0),
                            (57, 0),
                            (59, 0),
                            (61, 0),
                            (63, 0),
                            (65, 0),
                            (67, 0),
                            (69, 0),
                            (71, 0),
                            (73, 0),
                            (75, 0),
                            (77, 0),
                            (79, 0),
                            (81, 0),
                            (83, 0),
                            (85, 0),
                            (87, 0),
                            (89, 0),
                            (91, 0),
                            (93, 0),
                            (95, 0),
                            (97, 0),
                            (99, 0),
                            (101, 0),
                            (103, 0),
                            (105, 0),
                            (107, 0),
                            (109, 0),
                            (111, 0),
                            (113, 0),
                            (115, 0),
                            (117, 0),
                            (119, 0),
                            (121, 0),
                            (123, 0),
                            (125, 0),
                            (127, 0),
                            (129, 0),
                            (131, 0),
                            (133, 0),
                            (135, 0),
                            (137, 0),
                            (139, 0),
                            (141, 0),
                            (143, 0),
                            (145, 0),
                            (147, 0),
                            (149, 0),
                            (151, 0),
                            (153, 0),
                            (155, 0),
                            (157, 0),
                            (159, 0),
                            (161, 0),
                            (163, 0),
                            (165, 0),
                            (167, 0),
                            (169, 0),
                            (171, 0),
                            (173, 0),
                            (175, 0),
                            (177, 0),
                            (179, 0),
                            (181, 0),
                            (183, 0),
                            (185, 0),
                            (187, 0),
                            (189, 0),
                            (191, 0),
                            (193, 0),
                            (195, 0),
                            (197, 0),
                            (199, 0),
                        ],
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
                    adds: 100u64,
                    muls: 100u64,
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
                        rows: 100,
                        cols: 1,
                        nonzeros: &[
                            (0, 0),
                            (1, 0),
                            (2, 0),
                            (3, 0),
                            (4, 0),
                            (5, 0),
                            (6, 0),
                            (7, 0),
                            (8, 0),
                            (9, 0),
                            (10, 0),
                            (11, 0),
                            (12, 0),
                            (13, 0),
                            (14, 0),
                            (15, 0),
                            (16, 0),
                            (17, 0),
                            (18, 0),
                            (19, 0),
                            (20, 0),
                            (21, 0),
                            (22, 0),
                            (23, 0),
                            (24, 0),
                            (25, 0),
                            (26, 0),
                            (27, 0),
                            (28, 0),
                            (29, 0),
                            (30, 0),
                            (31, 0),
                            (32, 0),
                            (33, 0),
                            (34, 0),
                            (35, 0),
                            (36, 0),
                            (37, 0),
                            (38, 0),
                            (39, 0),
                            (40, 0),
                            (41, 0),
                            (42, 0),
                            (43, 0),
                            (44, 0),
                            (45, 0),
                            (46, 0),
                            (47, 0),
                            (48, 0),
                            (49, 0),
                            (50, 0),
                            (51, 0),
                            (52, 0),
                            (53, 0),
                            (54, 0),
                            (55, 0),
                            (56, 0),
                            (57, 0),
                            (58, 0),
                            (59, 0),
                            (60, 0),
                            (61, 0),
                            (62, 0),
                            (63, 0),
                            (64, 0),
                            (65, 0),
                            (66, 0),
                            (67, 0),
                            (68, 0),
                            (69, 0),
                            (70, 0),
                            (71, 0),
                            (72, 0),
                            (73, 0),
                            (74, 0),
                            (75, 0),
                            (76, 0),
                            (77, 0),
                            (78, 0),
                            (79, 0),
                            (80, 0),
                            (81, 0),
                            (82, 0),
                            (83, 0),
                            (84, 0),
                            (85, 0),
                            (86, 0),
                            (87, 0),
                            (88, 0),
                            (89, 0),
                            (90, 0),
                            (91, 0),
                            (92, 0),
                            (93, 0),
                            (94, 0),
                            (95, 0),
                            (96, 0),
                            (97, 0),
                            (98, 0),
                            (99, 0),
                        ],
                    },
                ],
                ops: ::zeitner::__private::OpCounts {
                    adds: 398u64,
                    muls: 201u64,
                    divs: 0u64,
                    transcendental: 0u64,
                    opaque_calls: 0u64,
                },
                ops_unshared: ::zeitner::__private::OpCounts {
                    adds: 398u64,
                    muls: 300u64,
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
                        rows: 100,
                        cols: 200,
                        nonzeros: &[
                            (0, 0),
                            (0, 1),
                            (1, 0),
                            (1, 1),
                            (1, 2),
                            (1, 3),
                            (2, 2),
                            (2, 3),
                            (2, 4),
                            (2, 5),
                            (3, 4),
                            (3, 5),
                            (3, 6),
                            (3, 7),
                            (4, 6),
                            (4, 7),
                            (4, 8),
                            (4, 9),
                            (5, 8),
                            (5, 9),
                            (5, 10),
                            (5, 11),
                            (6, 10),
                            (6, 11),
                            (6, 12),
                            (6, 13),
                            (7, 12),
                            (7, 13),
                            (7, 14),
                            (7, 15),
                            (8, 14),
                            (8, 15),
                            (8, 16),
                            (8, 17),
                            (9, 16),
                            (9, 17),
                            (9, 18),
                            (9, 19),
                            (10, 18),
                            (10, 19),
                            (10, 20),
                            (10, 21),
                            (11, 20),
                            (11, 21),
                            (11, 22),
                            (11, 23),
                            (12, 22),
                            (12, 23),
                            (12, 24),
                            (12, 25),
                            (13, 24),
                            (13, 25),
                            (13, 26),
                            (13, 27),
                            (14, 26),
                            (14, 27),
                            (14, 28),
                            (14, 29),
                            (15, 28),
                            (15, 29),
                            (15, 30),
                            (15, 31),
                            (16, 30),
                            (16, 31),
                            (16, 32),
                            (16, 33),
                            (17, 32),
                            (17, 33),
                            (17, 34),
                            (17, 35),
                            (18, 34),
                            (18, 35),
                            (18, 36),
                            (18, 37),
                            (19, 36),
                            (19, 37),
                            (19, 38),
                            (19, 39),
                            (20, 38),
                            (20, 39),
                            (20, 40),
                            (20, 41),
                            (21, 40),
                            (21, 41),
                            (21, 42),
                            (21, 43),
                            (22, 42),
                            (22, 43),
                            (22, 44),
                            (22, 45),
                            (23, 44),
                            (23, 45),
                            (23, 46),
                            (23, 47),
                            (24, 46),
                            (24, 47),
                            (24, 48),
                            (24, 49),
                            (25, 48),
                            (25, 49),
                            (25, 50),
                            (25, 51),
                            (26, 50),
                            (26, 51),
                            (26, 52),
                            (26, 53),
                            (27, 52),
                            (27, 53),
                            (27, 54),
                            (27, 55),
                            (28, 54),
                            (28, 55),
                            (28, 56),
                            (28, 57),
                            (29, 56),
                            (29, 57),
                            (29, 58),
                            (29, 59),
                            (30, 58),
                            (30, 59),
                            (30, 60),
                            (30, 61),
                            (31, 60),
                            (31, 61),
                            (31, 62),
                            (31, 63),
                            (32, 62),
                            (32, 63),
                            (32, 64),
                            (32, 65),
                            (33, 64),
                            (33, 65),
                            (33, 66),
                            (33, 67),
                            (34, 66),
                            (34, 67),
                            (34, 68),
                            (34, 69),
                            (35, 68),
                            (35, 69),
                            (35, 70),
                            (35, 71),
                            (36, 70),
                            (36, 71),
                            (36, 72),
                            (36, 73),
                            (37, 72),
                            (37, 73),
                            (37, 74),
                            (37, 75),
                            (38, 74),
                            (38, 75),
                            (38, 76),
                            (38, 77),
                            (39, 76),
                            (39, 77),
                            (39, 78),
                            (39, 79),
                            (40, 78),
                            (40, 79),
                            (40, 80),
                            (40, 81),
                            (41, 80),
                            (41, 81),
                            (41, 82),
                            (41, 83),
                            (42, 82),
                            (42, 83),
                            (42, 84),
                            (42, 85),
                            (43, 84),
                            (43, 85),
                            (43, 86),
                            (43, 87),
                            (44, 86),
                            (44, 87),
                            (44, 88),
                            (44, 89),
                            (45, 88),
                            (45, 89),
                            (45, 90),
                            (45, 91),
                            (46, 90),
                            (46, 91),
                            (46, 92),
                            (46, 93),
                            (47, 92),
                            (47, 93),
                            (47, 94),
                            (47, 95),
                            (48, 94),
                            (48, 95),
                            (48, 96),
                            (48, 97),
                            (49, 96),
                            (49, 97),
                            (49, 98),
                            (49, 99),
                            (50, 98),
                            (50, 99),
                            (50, 100),
                            (50, 101),
                            (51, 100),
                            (51, 101),
                            (51, 102),
                            (51, 103),
                            (52, 102),
                            (52, 103),
                            (52, 104),
                            (52, 105),
                            (53, 104),
                            (53, 105),
                            (53, 106),
                            (53, 107),
                            (54, 106),
                            (54, 107),
                            (54, 108),
                            (54, 109),
                            (55, 108),
                            (55, 109),
                            (55, 110),
                            (55, 111),
                            (56, 110),
                            (56, 111),
                            (56, 112),
                            (56, 113),
                            (57, 112),
                            (57, 113),
                            (57, 114),
                            (57, 115),
                            (58, 114),
                            (58, 115),
                            (58, 116),
                            (58, 117),
                            (59, 116),
                            (59, 117),
                            (59, 118),
                            (59, 119),
                            (60, 118),
                            (60, 119),
                            (60, 120),
                            (60, 121),
                            (61, 120),
                            (61, 121),
                            (61, 122),
                            (61, 123),
                            (62, 122),
                            (62, 123),
                            (62, 124),
                            (62, 125),
                            (63, 124),
                            (63, 125),
                            (63, 126),
                            (63, 127),
                            (64, 126),
                            (64, 127),
                            (64, 128),
                            (64, 129),
                            (65, 128),
                            (65, 129),
                            (65, 130),
                            (65, 131),
                            (66, 130),
                            (66, 131),
                            (66, 132),
                            (66, 133),
                            (67, 132),
                            (67, 133),
                            (67, 134),
                            (67, 135),
                            (68, 134),
                            (68, 135),
                            (68, 136),
                            (68, 137),
                            (69, 136),
                            (69, 137),
                            (69, 138),
                            (69, 139),
                            (70, 138),
                            (70, 139),
                            (70, 140),
                            (70, 141),
                            (71, 140),
                            (71, 141),
                            (71, 142),
                            (71, 143),
                            (72, 142),
                            (72, 143),
                            (72, 144),
                            (72, 145),
                            (73, 144),
                            (73, 145),
                            (73, 146),
                            (73, 147),
                            (74, 146),
                            (74, 147),
                            (74, 148),
                            (74, 149),
                            (75, 148),
                            (75, 149),
                            (75, 150),
                            (75, 151),
                            (76, 150),
                            (76, 151),
                            (76, 152),
                            (76, 153),
                            (77, 152),
                            (77, 153),
                            (77, 154),
                            (77, 155),
                            (78, 154),
                            (78, 155),
                            (78, 156),
                            (78, 157),
                            (79, 156),
                            (79, 157),
                            (79, 158),
                            (79, 159),
                            (80, 158),
                            (80, 159),
                            (80, 160),
                            (80, 161),
                            (81, 160),
                            (81, 161),
                            (81, 162),
                            (81, 163),
                            (82, 162),
                            (82, 163),
                            (82, 164),
                            (82, 165),
                            (83, 164),
                            (83, 165),
                            (83, 166),
                            (83, 167),
                            (84, 166),
                            (84, 167),
                            (84, 168),
                            (84, 169),
                            (85, 168),
                            (85, 169),
                            (85, 170),
                            (85, 171),
                            (86, 170),
                            (86, 171),
                            (86, 172),
                            (86, 173),
                            (87, 172),
                            (87, 173),
                            (87, 174),
                            (87, 175),
                            (88, 174),
                            (88, 175),
                            (88, 176),
                            (88, 177),
                            (89, 176),
                            (89, 177),
                            (89, 178),
                            (89, 179),
                            (90, 178),
                            (90, 179),
                            (90, 180),
                            (90, 181),
                            (91, 180),
                            (91, 181),
                            (91, 182),
                            (91, 183),
                            (92, 182),
                            (92, 183),
                            (92, 184),
                            (92, 185),
                            (93, 184),
                            (93, 185),
                            (93, 186),
                            (93, 187),
                            (94, 186),
                            (94, 187),
                            (94, 188),
                            (94, 189),
                            (95, 188),
                            (95, 189),
                            (95, 190),
                            (95, 191),
                            (96, 190),
                            (96, 191),
                            (96, 192),
                            (96, 193),
                            (97, 192),
                            (97, 193),
                            (97, 194),
                            (97, 195),
                            (98, 194),
                            (98, 195),
                            (98, 196),
                            (98, 197),
                            (99, 196),
                            (99, 197),
                            (99, 198),
                            (99, 199),
                        ],
                    },
                ],
                ops: ::zeitner::__private::OpCounts {
                    adds: 396u64,
                    muls: 200u64,
                    divs: 0u64,
                    transcendental: 0u64,
                    opaque_calls: 0u64,
                },
                ops_unshared: ::zeitner::__private::OpCounts {
                    adds: 594u64,
                    muls: 398u64,
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
                        rows: 100,
                        cols: 1,
                        nonzeros: &[
                            (0, 0),
                            (1, 0),
                            (2, 0),
                            (3, 0),
                            (4, 0),
                            (5, 0),
                            (6, 0),
                            (7, 0),
                            (8, 0),
                            (9, 0),
                            (10, 0),
                            (11, 0),
                            (12, 0),
                            (13, 0),
                            (14, 0),
                            (15, 0),
                            (16, 0),
                            (17, 0),
                            (18, 0),
                            (19, 0),
                            (20, 0),
                            (21, 0),
                            (22, 0),
                            (23, 0),
                            (24, 0),
                            (25, 0),
                            (26, 0),
                            (27, 0),
                            (28, 0),
                            (29, 0),
                            (30, 0),
                            (31, 0),
                            (32, 0),
                            (33, 0),
                            (34, 0),
                            (35, 0),
                            (36, 0),
                            (37, 0),
                            (38, 0),
                            (39, 0),
                            (40, 0),
                            (41, 0),
                            (42, 0),
                            (43, 0),
                            (44, 0),
                            (45, 0),
                            (46, 0),
                            (47, 0),
                            (48, 0),
                            (49, 0),
                            (50, 0),
                            (51, 0),
                            (52, 0),
                            (53, 0),
                            (54, 0),
                            (55, 0),
                            (56, 0),
                            (57, 0),
                            (58, 0),
                            (59, 0),
                            (60, 0),
                            (61, 0),
                            (62, 0),
                            (63, 0),
                            (64, 0),
                            (65, 0),
                            (66, 0),
                            (67, 0),
                            (68, 0),
                            (69, 0),
                            (70, 0),
                            (71, 0),
                            (72, 0),
                            (73, 0),
                            (74, 0),
                            (75, 0),
                            (76, 0),
                            (77, 0),
                            (78, 0),
                            (79, 0),
                            (80, 0),
                            (81, 0),
                            (82, 0),
                            (83, 0),
                            (84, 0),
                            (85, 0),
                            (86, 0),
                            (87, 0),
                            (88, 0),
                            (89, 0),
                            (90, 0),
                            (91, 0),
                            (92, 0),
                            (93, 0),
                            (94, 0),
                            (95, 0),
                            (96, 0),
                            (97, 0),
                            (98, 0),
                            (99, 0),
                        ],
                    },
                ],
                ops: ::zeitner::__private::OpCounts {
                    adds: 595u64,
                    muls: 598u64,
                    divs: 0u64,
                    transcendental: 0u64,
                    opaque_calls: 0u64,
                },
                ops_unshared: ::zeitner::__private::OpCounts {
                    adds: 793u64,
                    muls: 796u64,
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
                        rows: 100,
                        cols: 1,
                        nonzeros: &[
                            (0, 0),
                            (1, 0),
                            (2, 0),
                            (3, 0),
                            (4, 0),
                            (5, 0),
                            (6, 0),
                            (7, 0),
                            (8, 0),
                            (9, 0),
                            (10, 0),
                            (11, 0),
                            (12, 0),
                            (13, 0),
                            (14, 0),
                            (15, 0),
                            (16, 0),
                            (17, 0),
                            (18, 0),
                            (19, 0),
                            (20, 0),
                            (21, 0),
                            (22, 0),
                            (23, 0),
                            (24, 0),
                            (25, 0),
                            (26, 0),
                            (27, 0),
                            (28, 0),
                            (29, 0),
                            (30, 0),
                            (31, 0),
                            (32, 0),
                            (33, 0),
                            (34, 0),
                            (35, 0),
                            (36, 0),
                            (37, 0),
                            (38, 0),
                            (39, 0),
                            (40, 0),
                            (41, 0),
                            (42, 0),
                            (43, 0),
                            (44, 0),
                            (45, 0),
                            (46, 0),
                            (47, 0),
                            (48, 0),
                            (49, 0),
                            (50, 0),
                            (51, 0),
                            (52, 0),
                            (53, 0),
                            (54, 0),
                            (55, 0),
                            (56, 0),
                            (57, 0),
                            (58, 0),
                            (59, 0),
                            (60, 0),
                            (61, 0),
                            (62, 0),
                            (63, 0),
                            (64, 0),
                            (65, 0),
                            (66, 0),
                            (67, 0),
                            (68, 0),
                            (69, 0),
                            (70, 0),
                            (71, 0),
                            (72, 0),
                            (73, 0),
                            (74, 0),
                            (75, 0),
                            (76, 0),
                            (77, 0),
                            (78, 0),
                            (79, 0),
                            (80, 0),
                            (81, 0),
                            (82, 0),
                            (83, 0),
                            (84, 0),
                            (85, 0),
                            (86, 0),
                            (87, 0),
                            (88, 0),
                            (89, 0),
                            (90, 0),
                            (91, 0),
                            (92, 0),
                            (93, 0),
                            (94, 0),
                            (95, 0),
                            (96, 0),
                            (97, 0),
                            (98, 0),
                            (99, 0),
                        ],
                    },
                ],
                ops: ::zeitner::__private::OpCounts {
                    adds: 694u64,
                    muls: 798u64,
                    divs: 0u64,
                    transcendental: 0u64,
                    opaque_calls: 0u64,
                },
                ops_unshared: ::zeitner::__private::OpCounts {
                    adds: 694u64,
                    muls: 1192u64,
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
                        rows: 200,
                        cols: 200,
                        nonzeros: &[],
                    },
                    ::zeitner::__private::BlockSummary {
                        name: "dv",
                        rows: 200,
                        cols: 200,
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
                        rows: 200,
                        cols: 200,
                        nonzeros: &[
                            (0, 0),
                            (0, 2),
                            (1, 1),
                            (1, 3),
                            (2, 0),
                            (2, 2),
                            (2, 4),
                            (3, 1),
                            (3, 3),
                            (3, 5),
                            (4, 2),
                            (4, 4),
                            (4, 6),
                            (5, 3),
                            (5, 5),
                            (5, 7),
                            (6, 4),
                            (6, 6),
                            (6, 8),
                            (7, 5),
                            (7, 7),
                            (7, 9),
                            (8, 6),
                            (8, 8),
                            (8, 10),
                            (9, 7),
                            (9, 9),
                            (9, 11),
                            (10, 8),
                            (10, 10),
                            (10, 12),
                            (11, 9),
                            (11, 11),
                            (11, 13),
                            (12, 10),
                            (12, 12),
                            (12, 14),
                            (13, 11),
                            (13, 13),
                            (13, 15),
                            (14, 12),
                            (14, 14),
                            (14, 16),
                            (15, 13),
                            (15, 15),
                            (15, 17),
                            (16, 14),
                            (16, 16),
                            (16, 18),
                            (17, 15),
                            (17, 17),
                            (17, 19),
                            (18, 16),
                            (18, 18),
                            (18, 20),
                            (19, 17),
                            (19, 19),
                            (19, 21),
                            (20, 18),
                            (20, 20),
                            (20, 22),
                            (21, 19),
                            (21, 21),
                            (21, 23),
                            (22, 20),
                            (22, 22),
                            (22, 24),
                            (23, 21),
                            (23, 23),
                            (23, 25),
                            (24, 22),
                            (24, 24),
                            (24, 26),
                            (25, 23),
                            (25, 25),
                            (25, 27),
                            (26, 24),
                            (26, 26),
                            (26, 28),
                            (27, 25),
                            (27, 27),
                            (27, 29),
                            (28, 26),
                            (28, 28),
                            (28, 30),
                            (29, 27),
                            (29, 29),
                            (29, 31),
                            (30, 28),
                            (30, 30),
                            (30, 32),
                            (31, 29),
                            (31, 31),
                            (31, 33),
                            (32, 30),
                            (32, 32),
                            (32, 34),
                            (33, 31),
                            (33, 33),
                            (33, 35),
                            (34, 32),
                            (34, 34),
                            (34, 36),
                            (35, 33),
                            (35, 35),
                            (35, 37),
                            (36, 34),
                            (36, 36),
                            (36, 38),
                            (37, 35),
                            (37, 37),
                            (37, 39),
                            (38, 36),
                            (38, 38),
                            (38, 40),
                            (39, 37),
                            (39, 39),
                            (39, 41),
                            (40, 38),
                            (40, 40),
                            (40, 42),
                            (41, 39),
                            (41, 41),
                            (41, 43),
                            (42, 40),
                            (42, 42),
                            (42, 44),
                            (43, 41),
                            (43, 43),
                            (43, 45),
                            (44, 42),
                            (44, 44),
                            (44, 46),
                            (45, 43),
                            (45, 45),
                            (45, 47),
                            (46, 44),
                            (46, 46),
                            (46, 48),
                            (47, 45),
                            (47, 47),
                            (47, 49),
                            (48, 46),
                            (48, 48),
                            (48, 50),
                            (49, 47),
                            (49, 49),
                            (49, 51),
                            (50, 48),
                            (50, 50),
                            (50, 52),
                            (51, 49),
                            (51, 51),
                            (51, 53),
                            (52, 50),
                            (52, 52),
                            (52, 54),
                            (53, 51),
                            (53, 53),
                            (53, 55),
                            (54, 52),
                            (54, 54),
                            (54, 56),
                            (55, 53),
                            (55, 55),
                            (55, 57),
                            (56, 54),
                            (56, 56),
                            (56, 58),
                            (57, 55),
                            (57, 57),
                            (57, 59),
                            (58, 56),
                            (58, 58),
                            (58, 60),
                            (59, 57),
                            (59, 59),
                            (59, 61),
                            (60, 58),
                            (60, 60),
                            (60, 62),
                            (61, 59),
                            (61, 61),
                            (61, 63),
                            (62, 60),
                            (62, 62),
                            (62, 64),
                            (63, 61),
                            (63, 63),
                            (63, 65),
                            (64, 62),
                            (64, 64),
                            (64, 66),
                            (65, 63),
                            (65, 65),
                            (65, 67),
                            (66, 64),
                            (66, 66),
                            (66, 68),
                            (67, 65),
                            (67, 67),
                            (67, 69),
                            (68, 66),
                            (68, 68),
                            (68, 70),
                            (69, 67),
                            (69, 69),
                            (69, 71),
                            (70, 68),
                            (70, 70),
                            (70, 72),
                            (71, 69),
                            (71, 71),
                            (71, 73),
                            (72, 70),
                            (72, 72),
                            (72, 74),
                            (73, 71),
                            (73, 73),
                            (73, 75),
                            (74, 72),
                            (74, 74),
                            (74, 76),
                            (75, 73),
                            (75, 75),
                            (75, 77),
                            (76, 74),
                            (76, 76),
                            (76, 78),
                            (77, 75),
                            (77, 77),
                            (77, 79),
                            (78, 76),
                            (78, 78),
                            (78, 80),
                            (79, 77),
                            (79, 79),
                            (79, 81),
                            (80, 78),
                            (80, 80),
                            (80, 82),
                            (81, 79),
                            (81, 81),
                            (81, 83),
                            (82, 80),
                            (82, 82),
                            (82, 84),
                            (83, 81),
                            (83, 83),
                            (83, 85),
                            (84, 82),
                            (84, 84),
                            (84, 86),
                            (85, 83),
                            (85, 85),
                            (85, 87),
                            (86, 84),
                            (86, 86),
                            (86, 88),
                            (87, 85),
                            (87, 87),
                            (87, 89),
                            (88, 86),
                            (88, 88),
                            (88, 90),
                            (89, 87),
                            (89, 89),
                            (89, 91),
                            (90, 88),
                            (90, 90),
                            (90, 92),
                            (91, 89),
                            (91, 91),
                            (91, 93),
                            (92, 90),
                            (92, 92),
                            (92, 94),
                            (93, 91),
                            (93, 93),
                            (93, 95),
                            (94, 92),
                            (94, 94),
                            (94, 96),
                            (95, 93),
                            (95, 95),
                            (95, 97),
                            (96, 94),
                            (96, 96),
                            (96, 98),
                            (97, 95),
                            (97, 97),
                            (97, 99),
                            (98, 96),
                            (98, 98),
                            (98, 100),
                            (99, 97),
                            (99, 99),
                            (99, 101),
                            (100, 98),
                            (100, 100),
                            (100, 102),
                            (101, 99),
                            (101, 101),
                            (101, 103),
                            (102, 100),
                            (102, 102),
                            (102, 104),
                            (103, 101),
                            (103, 103),
                            (103, 105),
                            (104, 102),
                            (104, 104),
                            (104, 106),
                            (105, 103),
                            (105, 105),
                            (105, 107),
                            (106, 104),
                            (106, 106),
                            (106, 108),
                            (107, 105),
                            (107, 107),
                            (107, 109),
                            (108, 106),
                            (108, 108),
                            (108, 110),
                            (109, 107),
                            (109, 109),
                            (109, 111),
                            (110, 108),
                            (110, 110),
                            (110, 112),
                            (111, 109),
                            (111, 111),
                            (111, 113),
                            (112, 110),
                            (112, 112),
                            (112, 114),
                            (113, 111),
                            (113, 113),
                            (113, 115),
                            (114, 112),
                            (114, 114),
                            (114, 116),
                            (115, 113),
                            (115, 115),
                            (115, 117),
                            (116, 114),
                            (116, 116),
                            (116, 118),
                            (117, 115),
                            (117, 117),
                            (117, 119),
                            (118, 116),
                            (118, 118),
                            (118, 120),
                            (119, 117),
                            (119, 119),
                            (119, 121),
                            (120, 118),
                            (120, 120),
                            (120, 122),
                            (121, 119),
                            (121, 121),
                            (121, 123),
                            (122, 120),
                            (122, 122),
                            (122, 124),
                            (123, 121),
                            (123, 123),
                            (123, 125),
                            (124, 122),
                            (124, 124),
                            (124, 126),
                            (125, 123),
                            (125, 125),
                            (125, 127),
                            (126, 124),
                            (126, 126),
                            (126, 128),
                            (127, 125),
                            (127, 127),
                            (127, 129),
                            (128, 126),
                            (128, 128),
                            (128, 130),
                            (129, 127),
                            (129, 129),
                            (129, 131),
                            (130, 128),
                            (130, 130),
                            (130, 132),
                            (131, 129),
                            (131, 131),
                            (131, 133),
                            (132, 130),
                            (132, 132),
                            (132, 134),
                            (133, 131),
                            (133, 133),
                            (133, 135),
                            (134, 132),
                            (134, 134),
                            (134, 136),
                            (135, 133),
                            (135, 135),
                            (135, 137),
                            (136, 134),
                            (136, 136),
                            (136, 138),
                            (137, 135),
                            (137, 137),
                            (137, 139),
                            (138, 136),
                            (138, 138),
                            (138, 140),
                            (139, 137),
                            (139, 139),
                            (139, 141),
                            (140, 138),
                            (140, 140),
                            (140, 142),
                            (141, 139),
                            (141, 141),
                            (141, 143),
                            (142, 140),
                            (142, 142),
                            (142, 144),
                            (143, 141),
                            (143, 143),
                            (143, 145),
                            (144, 142),
                            (144, 144),
                            (144, 146),
                            (145, 143),
                            (145, 145),
                            (145, 147),
                            (146, 144),
                            (146, 146),
                            (146, 148),
                            (147, 145),
                            (147, 147),
                            (147, 149),
                            (148, 146),
                            (148, 148),
                            (148, 150),
                            (149, 147),
                            (149, 149),
                            (149, 151),
                            (150, 148),
                            (150, 150),
                            (150, 152),
                            (151, 149),
                            (151, 151),
                            (151, 153),
                            (152, 150),
                            (152, 152),
                            (152, 154),
                            (153, 151),
                            (153, 153),
                            (153, 155),
                            (154, 152),
                            (154, 154),
                            (154, 156),
                            (155, 153),
                            (155, 155),
                            (155, 157),
                            (156, 154),
                            (156, 156),
                            (156, 158),
                            (157, 155),
                            (157, 157),
                            (157, 159),
                            (158, 156),
                            (158, 158),
                            (158, 160),
                            (159, 157),
                            (159, 159),
                            (159, 161),
                            (160, 158),
                            (160, 160),
                            (160, 162),
                            (161, 159),
                            (161, 161),
                            (161, 163),
                            (162, 160),
                            (162, 162),
                            (162, 164),
                            (163, 161),
                            (163, 163),
                            (163, 165),
                            (164, 162),
                            (164, 164),
                            (164, 166),
                            (165, 163),
                            (165, 165),
                            (165, 167),
                            (166, 164),
                            (166, 166),
                            (166, 168),
                            (167, 165),
                            (167, 167),
                            (167, 169),
                            (168, 166),
                            (168, 168),
                            (168, 170),
                            (169, 167),
                            (169, 169),
                            (169, 171),
                            (170, 168),
                            (170, 170),
                            (170, 172),
                            (171, 169),
                            (171, 171),
                            (171, 173),
                            (172, 170),
                            (172, 172),
                            (172, 174),
                            (173, 171),
                            (173, 173),
                            (173, 175),
                            (174, 172),
                            (174, 174),
                            (174, 176),
                            (175, 173),
                            (175, 175),
                            (175, 177),
                            (176, 174),
                            (176, 176),
                            (176, 178),
                            (177, 175),
                            (177, 177),
                            (177, 179),
                            (178, 176),
                            (178, 178),
                            (178, 180),
                            (179, 177),
                            (179, 179),
                            (179, 181),
                            (180, 178),
                            (180, 180),
                            (180, 182),
                            (181, 179),
                            (181, 181),
                            (181, 183),
                            (182, 180),
                            (182, 182),
                            (182, 184),
                            (183, 181),
                            (183, 183),
                            (183, 185),
                            (184, 182),
                            (184, 184),
                            (184, 186),
                            (185, 183),
                            (185, 185),
                            (185, 187),
                            (186, 184),
                            (186, 186),
                            (186, 188),
                            (187, 185),
                            (187, 187),
                            (187, 189),
                            (188, 186),
                            (188, 188),
                            (188, 190),
                            (189, 187),
                            (189, 189),
                            (189, 191),
                            (190, 188),
                            (190, 190),
                            (190, 192),
                            (191, 189),
                            (191, 191),
                            (191, 193),
                            (192, 190),
                            (192, 192),
                            (192, 194),
                            (193, 191),
                            (193, 193),
                            (193, 195),
                            (194, 192),
                            (194, 194),
                            (194, 196),
                            (195, 193),
                            (195, 195),
                            (195, 197),
                            (196, 194),
                            (196, 196),
                            (196, 198),
                            (197, 195),
                            (197, 197),
                            (197, 199),
                            (198, 196),
                            (198, 198),
                            (199, 197),
                            (199, 199),
                        ],
                    },
                    ::zeitner::__private::BlockSummary {
                        name: "dv",
                        rows: 200,
                        cols: 200,
                        nonzeros: &[],
                    },
                ],
                ops: ::zeitner::__private::OpCounts {
                    adds: 198u64,
                    muls: 199u64,
                    divs: 0u64,
                    transcendental: 0u64,
                    opaque_calls: 0u64,
                },
                ops_unshared: ::zeitner::__private::OpCounts {
                    adds: 396u64,
                    muls: 794u64,
                    divs: 0u64,
                    transcendental: 0u64,
                    opaque_calls: 0u64,
                },
            },
        ],
    };
    type Mass = ::zeitner::__private::DiagonalMass<200>;
    type Storage = ::zeitner::__private::LargeSceneStorage;
    const SPARSITY: ::core::option::Option<::zeitner::__private::Sparsity> = ::core::option::Option::Some(::zeitner::__private::Sparsity {
        constraint_jacobian: &[
            (0, 0),
            (0, 1),
            (1, 0),
            (1, 1),
            (1, 2),
            (1, 3),
            (2, 2),
            (2, 3),
            (2, 4),
            (2, 5),
            (3, 4),
            (3, 5),
            (3, 6),
            (3, 7),
            (4, 6),
            (4, 7),
            (4, 8),
            (4, 9),
            (5, 8),
            (5, 9),
            (5, 10),
            (5, 11),
            (6, 10),
            (6, 11),
            (6, 12),
            (6, 13),
            (7, 12),
            (7, 13),
            (7, 14),
            (7, 15),
            (8, 14),
            (8, 15),
            (8, 16),
            (8, 17),
            (9, 16),
            (9, 17),
            (9, 18),
            (9, 19),
            (10, 18),
            (10, 19),
            (10, 20),
            (10, 21),
            (11, 20),
            (11, 21),
            (11, 22),
            (11, 23),
            (12, 22),
            (12, 23),
            (12, 24),
            (12, 25),
            (13, 24),
            (13, 25),
            (13, 26),
            (13, 27),
            (14, 26),
            (14, 27),
            (14, 28),
            (14, 29),
            (15, 28),
            (15, 29),
            (15, 30),
            (15, 31),
            (16, 30),
            (16, 31),
            (16, 32),
            (16, 33),
            (17, 32),
            (17, 33),
            (17, 34),
            (17, 35),
            (18, 34),
            (18, 35),
            (18, 36),
            (18, 37),
            (19, 36),
            (19, 37),
            (19, 38),
            (19, 39),
            (20, 38),
            (20, 39),
            (20, 40),
            (20, 41),
            (21, 40),
            (21, 41),
            (21, 42),
            (21, 43),
            (22, 42),
            (22, 43),
            (22, 44),
            (22, 45),
            (23, 44),
            (23, 45),
            (23, 46),
            (23, 47),
            (24, 46),
            (24, 47),
            (24, 48),
            (24, 49),
            (25, 48),
            (25, 49),
            (25, 50),
            (25, 51),
            (26, 50),
            (26, 51),
            (26, 52),
            (26, 53),
            (27, 52),
            (27, 53),
            (27, 54),
            (27, 55),
            (28, 54),
            (28, 55),
            (28, 56),
            (28, 57),
            (29, 56),
            (29, 57),
            (29, 58),
            (29, 59),
            (30, 58),
            (30, 59),
            (30, 60),
            (30, 61),
            (31, 60),
            (31, 61),
            (31, 62),
            (31, 63),
            (32, 62),
            (32, 63),
            (32, 64),
            (32, 65),
            (33, 64),
            (33, 65),
            (33, 66),
            (33, 67),
            (34, 66),
            (34, 67),
            (34, 68),
            (34, 69),
            (35, 68),
            (35, 69),
            (35, 70),
            (35, 71),
            (36, 70),
            (36, 71),
            (36, 72),
            (36, 73),
            (37, 72),
            (37, 73),
            (37, 74),
            (37, 75),
            (38, 74),
            (38, 75),
            (38, 76),
            (38, 77),
            (39, 76),
            (39, 77),
            (39, 78),
            (39, 79),
            (40, 78),
            (40, 79),
            (40, 80),
            (40, 81),
            (41, 80),
            (41, 81),
            (41, 82),
            (41, 83),
            (42, 82),
            (42, 83),
            (42, 84),
            (42, 85),
            (43, 84),
            (43, 85),
            (43, 86),
            (43, 87),
            (44, 86),
            (44, 87),
            (44, 88),
            (44, 89),
            (45, 88),
            (45, 89),
            (45, 90),
            (45, 91),
            (46, 90),
            (46, 91),
            (46, 92),
            (46, 93),
            (47, 92),
            (47, 93),
            (47, 94),
            (47, 95),
            (48, 94),
            (48, 95),
            (48, 96),
            (48, 97),
            (49, 96),
            (49, 97),
            (49, 98),
            (49, 99),
            (50, 98),
            (50, 99),
            (50, 100),
            (50, 101),
            (51, 100),
            (51, 101),
            (51, 102),
            (51, 103),
            (52, 102),
            (52, 103),
            (52, 104),
            (52, 105),
            (53, 104),
            (53, 105),
            (53, 106),
            (53, 107),
            (54, 106),
            (54, 107),
            (54, 108),
            (54, 109),
            (55, 108),
            (55, 109),
            (55, 110),
            (55, 111),
            (56, 110),
            (56, 111),
            (56, 112),
            (56, 113),
            (57, 112),
            (57, 113),
            (57, 114),
            (57, 115),
            (58, 114),
            (58, 115),
            (58, 116),
            (58, 117),
            (59, 116),
            (59, 117),
            (59, 118),
            (59, 119),
            (60, 118),
            (60, 119),
            (60, 120),
            (60, 121),
            (61, 120),
            (61, 121),
            (61, 122),
            (61, 123),
            (62, 122),
            (62, 123),
            (62, 124),
            (62, 125),
            (63, 124),
            (63, 125),
            (63, 126),
            (63, 127),
            (64, 126),
            (64, 127),
            (64, 128),
            (64, 129),
            (65, 128),
            (65, 129),
            (65, 130),
            (65, 131),
            (66, 130),
            (66, 131),
            (66, 132),
            (66, 133),
            (67, 132),
            (67, 133),
            (67, 134),
            (67, 135),
            (68, 134),
            (68, 135),
            (68, 136),
            (68, 137),
            (69, 136),
            (69, 137),
            (69, 138),
            (69, 139),
            (70, 138),
            (70, 139),
            (70, 140),
            (70, 141),
            (71, 140),
            (71, 141),
            (71, 142),
            (71, 143),
            (72, 142),
            (72, 143),
            (72, 144),
            (72, 145),
            (73, 144),
            (73, 145),
            (73, 146),
            (73, 147),
            (74, 146),
            (74, 147),
            (74, 148),
            (74, 149),
            (75, 148),
            (75, 149),
            (75, 150),
            (75, 151),
            (76, 150),
            (76, 151),
            (76, 152),
            (76, 153),
            (77, 152),
            (77, 153),
            (77, 154),
            (77, 155),
            (78, 154),
            (78, 155),
            (78, 156),
            (78, 157),
            (79, 156),
            (79, 157),
            (79, 158),
            (79, 159),
            (80, 158),
            (80, 159),
            (80, 160),
            (80, 161),
            (81, 160),
            (81, 161),
            (81, 162),
            (81, 163),
            (82, 162),
            (82, 163),
            (82, 164),
            (82, 165),
            (83, 164),
            (83, 165),
            (83, 166),
            (83, 167),
            (84, 166),
            (84, 167),
            (84, 168),
            (84, 169),
            (85, 168),
            (85, 169),
            (85, 170),
            (85, 171),
            (86, 170),
            (86, 171),
            (86, 172),
            (86, 173),
            (87, 172),
            (87, 173),
            (87, 174),
            (87, 175),
            (88, 174),
            (88, 175),
            (88, 176),
            (88, 177),
            (89, 176),
            (89, 177),
            (89, 178),
            (89, 179),
            (90, 178),
            (90, 179),
            (90, 180),
            (90, 181),
            (91, 180),
            (91, 181),
            (91, 182),
            (91, 183),
            (92, 182),
            (92, 183),
            (92, 184),
            (92, 185),
            (93, 184),
            (93, 185),
            (93, 186),
            (93, 187),
            (94, 186),
            (94, 187),
            (94, 188),
            (94, 189),
            (95, 188),
            (95, 189),
            (95, 190),
            (95, 191),
            (96, 190),
            (96, 191),
            (96, 192),
            (96, 193),
            (97, 192),
            (97, 193),
            (97, 194),
            (97, 195),
            (98, 194),
            (98, 195),
            (98, 196),
            (98, 197),
            (99, 196),
            (99, 197),
            (99, 198),
            (99, 199),
        ],
        force_jacobians: [&[], &[]],
        constraint_force_jacobians: [
            &[
                (0, 0),
                (0, 2),
                (1, 1),
                (1, 3),
                (2, 0),
                (2, 2),
                (2, 4),
                (3, 1),
                (3, 3),
                (3, 5),
                (4, 2),
                (4, 4),
                (4, 6),
                (5, 3),
                (5, 5),
                (5, 7),
                (6, 4),
                (6, 6),
                (6, 8),
                (7, 5),
                (7, 7),
                (7, 9),
                (8, 6),
                (8, 8),
                (8, 10),
                (9, 7),
                (9, 9),
                (9, 11),
                (10, 8),
                (10, 10),
                (10, 12),
                (11, 9),
                (11, 11),
                (11, 13),
                (12, 10),
                (12, 12),
                (12, 14),
                (13, 11),
                (13, 13),
                (13, 15),
                (14, 12),
                (14, 14),
                (14, 16),
                (15, 13),
                (15, 15),
                (15, 17),
                (16, 14),
                (16, 16),
                (16, 18),
                (17, 15),
                (17, 17),
                (17, 19),
                (18, 16),
                (18, 18),
                (18, 20),
                (19, 17),
                (19, 19),
                (19, 21),
                (20, 18),
                (20, 20),
                (20, 22),
                (21, 19),
                (21, 21),
                (21, 23),
                (22, 20),
                (22, 22),
                (22, 24),
                (23, 21),
                (23, 23),
                (23, 25),
                (24, 22),
                (24, 24),
                (24, 26),
                (25, 23),
                (25, 25),
                (25, 27),
                (26, 24),
                (26, 26),
                (26, 28),
                (27, 25),
                (27, 27),
                (27, 29),
                (28, 26),
                (28, 28),
                (28, 30),
                (29, 27),
                (29, 29),
                (29, 31),
                (30, 28),
                (30, 30),
                (30, 32),
                (31, 29),
                (31, 31),
                (31, 33),
                (32, 30),
                (32, 32),
                (32, 34),
                (33, 31),
                (33, 33),
                (33, 35),
                (34, 32),
                (34, 34),
                (34, 36),
                (35, 33),
                (35, 35),
                (35, 37),
                (36, 34),
                (36, 36),
                (36, 38),
                (37, 35),
                (37, 37),
                (37, 39),
                (38, 36),
                (38, 38),
                (38, 40),
                (39, 37),
                (39, 39),
                (39, 41),
                (40, 38),
                (40, 40),
                (40, 42),
                (41, 39),
                (41, 41),
                (41, 43),
                (42, 40),
                (42, 42),
                (42, 44),
                (43, 41),
                (43, 43),
                (43, 45),
                (44, 42),
                (44, 44),
                (44, 46),
                (45, 43),
                (45, 45),
                (45, 47),
                (46, 44),
                (46, 46),
                (46, 48),
                (47, 45),
                (47, 47),
                (47, 49),
                (48, 46),
                (48, 48),
                (48, 50),
                (49, 47),
                (49, 49),
                (49, 51),
                (50, 48),
                (50, 50),
                (50, 52),
                (51, 49),
                (51, 51),
                (51, 53),
                (52, 50),
                (52, 52),
                (52, 54),
                (53, 51),
                (53, 53),
                (53, 55),
                (54, 52),
                (54, 54),
                (54, 56),
                (55, 53),
                (55, 55),
                (55, 57),
                (56, 54),
                (56, 56),
                (56, 58),
                (57, 55),
                (57, 57),
                (57, 59),
                (58, 56),
                (58, 58),
                (58, 60),
                (59, 57),
                (59, 59),
                (59, 61),
                (60, 58),
                (60, 60),
                (60, 62),
                (61, 59),
                (61, 61),
                (61, 63),
                (62, 60),
                (62, 62),
                (62, 64),
                (63, 61),
                (63, 63),
                (63, 65),
                (64, 62),
                (64, 64),
                (64, 66),
                (65, 63),
                (65, 65),
                (65, 67),
                (66, 64),
                (66, 66),
                (66, 68),
                (67, 65),
                (67, 67),
                (67, 69),
                (68, 66),
                (68, 68),
                (68, 70),
                (69, 67),
                (69, 69),
                (69, 71),
                (70, 68),
                (70, 70),
                (70, 72),
                (71, 69),
                (71, 71),
                (71, 73),
                (72, 70),
                (72, 72),
                (72, 74),
                (73, 71),
                (73, 73),
                (73, 75),
                (74, 72),
                (74, 74),
                (74, 76),
                (75, 73),
                (75, 75),
                (75, 77),
                (76, 74),
                (76, 76),
                (76, 78),
                (77, 75),
                (77, 77),
                (77, 79),
                (78, 76),
                (78, 78),
                (78, 80),
                (79, 77),
                (79, 79),
                (79, 81),
                (80, 78),
                (80, 80),
                (80, 82),
                (81, 79),
                (81, 81),
                (81, 83),
                (82, 80),
                (82, 82),
                (82, 84),
                (83, 81),
                (83, 83),
                (83, 85),
                (84, 82),
                (84, 84),
                (84, 86),
                (85, 83),
                (85, 85),
                (85, 87),
                (86, 84),
                (86, 86),
                (86, 88),
                (87, 85),
                (87, 87),
                (87, 89),
                (88, 86),
                (88, 88),
                (88, 90),
                (89, 87),
                (89, 89),
                (89, 91),
                (90, 88),
                (90, 90),
                (90, 92),
                (91, 89),
                (91, 91),
                (91, 93),
                (92, 90),
                (92, 92),
                (92, 94),
                (93, 91),
                (93, 93),
                (93, 95),
                (94, 92),
                (94, 94),
                (94, 96),
                (95, 93),
                (95, 95),
                (95, 97),
                (96, 94),
                (96, 96),
                (96, 98),
                (97, 95),
                (97, 97),
                (97, 99),
                (98, 96),
                (98, 98),
                (98, 100),
                (99, 97),
                (99, 99),
                (99, 101),
                (100, 98),
                (100, 100),
                (100, 102),
                (101, 99),
                (101, 101),
                (101, 103),
                (102, 100),
                (102, 102),
                (102, 104),
                (103, 101),
                (103, 103),
                (103, 105),
                (104, 102),
                (104, 104),
                (104, 106),
                (105, 103),
                (105, 105),
                (105, 107),
                (106, 104),
                (106, 106),
                (106, 108),
                (107, 105),
                (107, 107),
                (107, 109),
                (108, 106),
                (108, 108),
                (108, 110),
                (109, 107),
                (109, 109),
                (109, 111),
                (110, 108),
                (110, 110),
                (110, 112),
                (111, 109),
                (111, 111),
                (111, 113),
                (112, 110),
                (112, 112),
                (112, 114),
                (113, 111),
                (113, 113),
                (113, 115),
                (114, 112),
                (114, 114),
                (114, 116),
                (115, 113),
                (115, 115),
                (115, 117),
                (116, 114),
                (116, 116),
                (116, 118),
                (117, 115),
                (117, 117),
                (117, 119),
                (118, 116),
                (118, 118),
                (118, 120),
                (119, 117),
                (119, 119),
                (119, 121),
                (120, 118),
                (120, 120),
                (120, 122),
                (121, 119),
                (121, 121),
                (121, 123),
                (122, 120),
                (122, 122),
                (122, 124),
                (123, 121),
                (123, 123),
                (123, 125),
                (124, 122),
                (124, 124),
                (124, 126),
                (125, 123),
                (125, 125),
                (125, 127),
                (126, 124),
                (126, 126),
                (126, 128),
                (127, 125),
                (127, 127),
                (127, 129),
                (128, 126),
                (128, 128),
                (128, 130),
                (129, 127),
                (129, 129),
                (129, 131),
                (130, 128),
                (130, 130),
                (130, 132),
                (131, 129),
                (131, 131),
                (131, 133),
                (132, 130),
                (132, 132),
                (132, 134),
                (133, 131),
                (133, 133),
                (133, 135),
                (134, 132),
                (134, 134),
                (134, 136),
                (135, 133),
                (135, 135),
                (135, 137),
                (136, 134),
                (136, 136),
                (136, 138),
                (137, 135),
                (137, 137),
                (137, 139),
                (138, 136),
                (138, 138),
                (138, 140),
                (139, 137),
                (139, 139),
                (139, 141),
                (140, 138),
                (140, 140),
                (140, 142),
                (141, 139),
                (141, 141),
                (141, 143),
                (142, 140),
                (142, 142),
                (142, 144),
                (143, 141),
                (143, 143),
                (143, 145),
                (144, 142),
                (144, 144),
                (144, 146),
                (145, 143),
                (145, 145),
                (145, 147),
                (146, 144),
                (146, 146),
                (146, 148),
                (147, 145),
                (147, 147),
                (147, 149),
                (148, 146),
                (148, 148),
                (148, 150),
                (149, 147),
                (149, 149),
                (149, 151),
                (150, 148),
                (150, 150),
                (150, 152),
                (151, 149),
                (151, 151),
                (151, 153),
                (152, 150),
                (152, 152),
                (152, 154),
                (153, 151),
                (153, 153),
                (153, 155),
                (154, 152),
                (154, 154),
                (154, 156),
                (155, 153),
                (155, 155),
                (155, 157),
                (156, 154),
                (156, 156),
                (156, 158),
                (157, 155),
                (157, 157),
                (157, 159),
                (158, 156),
                (158, 158),
                (158, 160),
                (159, 157),
                (159, 159),
                (159, 161),
                (160, 158),
                (160, 160),
                (160, 162),
                (161, 159),
                (161, 161),
                (161, 163),
                (162, 160),
                (162, 162),
                (162, 164),
                (163, 161),
                (163, 163),
                (163, 165),
                (164, 162),
                (164, 164),
                (164, 166),
                (165, 163),
                (165, 165),
                (165, 167),
                (166, 164),
                (166, 166),
                (166, 168),
                (167, 165),
                (167, 167),
                (167, 169),
                (168, 166),
                (168, 168),
                (168, 170),
                (169, 167),
                (169, 169),
                (169, 171),
                (170, 168),
                (170, 170),
                (170, 172),
                (171, 169),
                (171, 171),
                (171, 173),
                (172, 170),
                (172, 172),
                (172, 174),
                (173, 171),
                (173, 173),
                (173, 175),
                (174, 172),
                (174, 174),
                (174, 176),
                (175, 173),
                (175, 175),
                (175, 177),
                (176, 174),
                (176, 176),
                (176, 178),
                (177, 175),
                (177, 177),
                (177, 179),
                (178, 176),
                (178, 178),
                (178, 180),
                (179, 177),
                (179, 179),
                (179, 181),
                (180, 178),
                (180, 180),
                (180, 182),
                (181, 179),
                (181, 181),
                (181, 183),
                (182, 180),
                (182, 182),
                (182, 184),
                (183, 181),
                (183, 183),
                (183, 185),
                (184, 182),
                (184, 184),
                (184, 186),
                (185, 183),
                (185, 185),
                (185, 187),
                (186, 184),
                (186, 186),
                (186, 188),
                (187, 185),
                (187, 187),
                (187, 189),
                (188, 186),
                (188, 188),
                (188, 190),
                (189, 187),
                (189, 189),
                (189, 191),
                (190, 188),
                (190, 190),
                (190, 192),
                (191, 189),
                (191, 191),
                (191, 193),
                (192, 190),
                (192, 192),
                (192, 194),
                (193, 191),
                (193, 193),
                (193, 195),
                (194, 192),
                (194, 194),
                (194, 196),
                (195, 193),
                (195, 195),
                (195, 197),
                (196, 194),
                (196, 196),
                (196, 198),
                (197, 195),
                (197, 197),
                (197, 199),
                (198, 196),
                (198, 198),
                (199, 197),
                (199, 199),
            ],
            &[],
        ],
    });
    #[inline]
    fn mass_matrix(
        &self,
        q: &::zeitner::__private::Vector<200>,
        t: ::zeitner::__private::Float,
    ) -> Self::Mass {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let mut m = ::zeitner::__private::Vector::<200>::zeros();
        m[0] = self.m;
        m[1] = self.m;
        m[2] = self.m;
        m[3] = self.m;
        m[4] = self.m;
        m[5] = self.m;
        m[6] = self.m;
        m[7] = self.m;
        m[8] = self.m;
        m[9] = self.m;
        m[10] = self.m;
        m[11] = self.m;
        m[12] = self.m;
        m[13] = self.m;
        m[14] = self.m;
        m[15] = self.m;
        m[16] = self.m;
        m[17] = self.m;
        m[18] = self.m;
        m[19] = self.m;
        m[20] = self.m;
        m[21] = self.m;
        m[22] = self.m;
        m[23] = self.m;
        m[24] = self.m;
        m[25] = self.m;
        m[26] = self.m;
        m[27] = self.m;
        m[28] = self.m;
        m[29] = self.m;
        m[30] = self.m;
        m[31] = self.m;
        m[32] = self.m;
        m[33] = self.m;
        m[34] = self.m;
        m[35] = self.m;
        m[36] = self.m;
        m[37] = self.m;
        m[38] = self.m;
        m[39] = self.m;
        m[40] = self.m;
        m[41] = self.m;
        m[42] = self.m;
        m[43] = self.m;
        m[44] = self.m;
        m[45] = self.m;
        m[46] = self.m;
        m[47] = self.m;
        m[48] = self.m;
        m[49] = self.m;
        m[50] = self.m;
        m[51] = self.m;
        m[52] = self.m;
        m[53] = self.m;
        m[54] = self.m;
        m[55] = self.m;
        m[56] = self.m;
        m[57] = self.m;
        m[58] = self.m;
        m[59] = self.m;
        m[60] = self.m;
        m[61] = self.m;
        m[62] = self.m;
        m[63] = self.m;
        m[64] = self.m;
        m[65] = self.m;
        m[66] = self.m;
        m[67] = self.m;
        m[68] = self.m;
        m[69] = self.m;
        m[70] = self.m;
        m[71] = self.m;
        m[72] = self.m;
        m[73] = self.m;
        m[74] = self.m;
        m[75] = self.m;
        m[76] = self.m;
        m[77] = self.m;
        m[78] = self.m;
        m[79] = self.m;
        m[80] = self.m;
        m[81] = self.m;
        m[82] = self.m;
        m[83] = self.m;
        m[84] = self.m;
        m[85] = self.m;
        m[86] = self.m;
        m[87] = self.m;
        m[88] = self.m;
        m[89] = self.m;
        m[90] = self.m;
        m[91] = self.m;
        m[92] = self.m;
        m[93] = self.m;
        m[94] = self.m;
        m[95] = self.m;
        m[96] = self.m;
        m[97] = self.m;
        m[98] = self.m;
        m[99] = self.m;
        m[100] = self.m;
        m[101] = self.m;
        m[102] = self.m;
        m[103] = self.m;
        m[104] = self.m;
        m[105] = self.m;
        m[106] = self.m;
        m[107] = self.m;
        m[108] = self.m;
        m[109] = self.m;
        m[110] = self.m;
        m[111] = self.m;
        m[112] = self.m;
        m[113] = self.m;
        m[114] = self.m;
        m[115] = self.m;
        m[116] = self.m;
        m[117] = self.m;
        m[118] = self.m;
        m[119] = self.m;
        m[120] = self.m;
        m[121] = self.m;
        m[122] = self.m;
        m[123] = self.m;
        m[124] = self.m;
        m[125] = self.m;
        m[126] = self.m;
        m[127] = self.m;
        m[128] = self.m;
        m[129] = self.m;
        m[130] = self.m;
        m[131] = self.m;
        m[132] = self.m;
        m[133] = self.m;
        m[134] = self.m;
        m[135] = self.m;
        m[136] = self.m;
        m[137] = self.m;
        m[138] = self.m;
        m[139] = self.m;
        m[140] = self.m;
        m[141] = self.m;
        m[142] = self.m;
        m[143] = self.m;
        m[144] = self.m;
        m[145] = self.m;
        m[146] = self.m;
        m[147] = self.m;
        m[148] = self.m;
        m[149] = self.m;
        m[150] = self.m;
        m[151] = self.m;
        m[152] = self.m;
        m[153] = self.m;
        m[154] = self.m;
        m[155] = self.m;
        m[156] = self.m;
        m[157] = self.m;
        m[158] = self.m;
        m[159] = self.m;
        m[160] = self.m;
        m[161] = self.m;
        m[162] = self.m;
        m[163] = self.m;
        m[164] = self.m;
        m[165] = self.m;
        m[166] = self.m;
        m[167] = self.m;
        m[168] = self.m;
        m[169] = self.m;
        m[170] = self.m;
        m[171] = self.m;
        m[172] = self.m;
        m[173] = self.m;
        m[174] = self.m;
        m[175] = self.m;
        m[176] = self.m;
        m[177] = self.m;
        m[178] = self.m;
        m[179] = self.m;
        m[180] = self.m;
        m[181] = self.m;
        m[182] = self.m;
        m[183] = self.m;
        m[184] = self.m;
        m[185] = self.m;
        m[186] = self.m;
        m[187] = self.m;
        m[188] = self.m;
        m[189] = self.m;
        m[190] = self.m;
        m[191] = self.m;
        m[192] = self.m;
        m[193] = self.m;
        m[194] = self.m;
        m[195] = self.m;
        m[196] = self.m;
        m[197] = self.m;
        m[198] = self.m;
        m[199] = self.m;
        ::zeitner::__private::DiagonalMass(m)
    }
    #[inline]
    fn applied_force(
        &self,
        q: &::zeitner::__private::Vector<200>,
        v: &::zeitner::__private::Vector<200>,
        t: ::zeitner::__private::Float,
    ) -> ::zeitner::__private::Vector<200> {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let s0 = -(self.m * self.g);
        let mut f = ::zeitner::__private::Vector::<200>::zeros();
        f[1] = s0;
        f[3] = s0;
        f[5] = s0;
        f[7] = s0;
        f[9] = s0;
        f[11] = s0;
        f[13] = s0;
        f[15] = s0;
        f[17] = s0;
        f[19] = s0;
        f[21] = s0;
        f[23] = s0;
        f[25] = s0;
        f[27] = s0;
        f[29] = s0;
        f[31] = s0;
        f[33] = s0;
        f[35] = s0;
        f[37] = s0;
        f[39] = s0;
        f[41] = s0;
        f[43] = s0;
        f[45] = s0;
        f[47] = s0;
        f[49] = s0;
        f[51] = s0;
        f[53] = s0;
        f[55] = s0;
        f[57] = s0;
        f[59] = s0;
        f[61] = s0;
        f[63] = s0;
        f[65] = s0;
        f[67] = s0;
        f[69] = s0;
        f[71] = s0;
        f[73] = s0;
        f[75] = s0;
        f[77] = s0;
        f[79] = s0;
        f[81] = s0;
        f[83] = s0;
        f[85] = s0;
        f[87] = s0;
        f[89] = s0;
        f[91] = s0;
        f[93] = s0;
        f[95] = s0;
        f[97] = s0;
        f[99] = s0;
        f[101] = s0;
        f[103] = s0;
        f[105] = s0;
        f[107] = s0;
        f[109] = s0;
        f[111] = s0;
        f[113] = s0;
        f[115] = s0;
        f[117] = s0;
        f[119] = s0;
        f[121] = s0;
        f[123] = s0;
        f[125] = s0;
        f[127] = s0;
        f[129] = s0;
        f[131] = s0;
        f[133] = s0;
        f[135] = s0;
        f[137] = s0;
        f[139] = s0;
        f[141] = s0;
        f[143] = s0;
        f[145] = s0;
        f[147] = s0;
        f[149] = s0;
        f[151] = s0;
        f[153] = s0;
        f[155] = s0;
        f[157] = s0;
        f[159] = s0;
        f[161] = s0;
        f[163] = s0;
        f[165] = s0;
        f[167] = s0;
        f[169] = s0;
        f[171] = s0;
        f[173] = s0;
        f[175] = s0;
        f[177] = s0;
        f[179] = s0;
        f[181] = s0;
        f[183] = s0;
        f[185] = s0;
        f[187] = s0;
        f[189] = s0;
        f[191] = s0;
        f[193] = s0;
        f[195] = s0;
        f[197] = s0;
        f[199] = s0;
        f
    }
    #[inline]
    fn constraint_residual(
        &self,
        q: &::zeitner::__private::Vector<200>,
        v: &::zeitner::__private::Vector<200>,
        t: ::zeitner::__private::Float,
    ) -> ::zeitner::__private::Vector<100> {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let s0 = self.l.powi(2);
        let mut g = ::zeitner::__private::Vector::<100>::zeros();
        g[0] = q[0].powi(2) + q[1].powi(2) - s0;
        g[1] = (q[2] - q[0]).powi(2) + (q[3] - q[1]).powi(2) - s0;
        g[2] = (q[4] - q[2]).powi(2) + (q[5] - q[3]).powi(2) - s0;
        g[3] = (q[6] - q[4]).powi(2) + (q[7] - q[5]).powi(2) - s0;
        g[4] = (q[8] - q[6]).powi(2) + (q[9] - q[7]).powi(2) - s0;
        g[5] = (q[10] - q[8]).powi(2) + (q[11] - q[9]).powi(2) - s0;
        g[6] = (q[12] - q[10]).powi(2) + (q[13] - q[11]).powi(2) - s0;
        g[7] = (q[14] - q[12]).powi(2) + (q[15] - q[13]).powi(2) - s0;
        g[8] = (q[16] - q[14]).powi(2) + (q[17] - q[15]).powi(2) - s0;
        g[9] = (q[18] - q[16]).powi(2) + (q[19] - q[17]).powi(2) - s0;
        g[10] = (q[20] - q[18]).powi(2) + (q[21] - q[19]).powi(2) - s0;
        g[11] = (q[22] - q[20]).powi(2) + (q[23] - q[21]).powi(2) - s0;
        g[12] = (q[24] - q[22]).powi(2) + (q[25] - q[23]).powi(2) - s0;
        g[13] = (q[26] - q[24]).powi(2) + (q[27] - q[25]).powi(2) - s0;
        g[14] = (q[28] - q[26]).powi(2) + (q[29] - q[27]).powi(2) - s0;
        g[15] = (q[30] - q[28]).powi(2) + (q[31] - q[29]).powi(2) - s0;
        g[16] = (q[32] - q[30]).powi(2) + (q[33] - q[31]).powi(2) - s0;
        g[17] = (q[34] - q[32]).powi(2) + (q[35] - q[33]).powi(2) - s0;
        g[18] = (q[36] - q[34]).powi(2) + (q[37] - q[35]).powi(2) - s0;
        g[19] = (q[38] - q[36]).powi(2) + (q[39] - q[37]).powi(2) - s0;
        g[20] = (q[40] - q[38]).powi(2) + (q[41] - q[39]).powi(2) - s0;
        g[21] = (q[42] - q[40]).powi(2) + (q[43] - q[41]).powi(2) - s0;
        g[22] = (q[44] - q[42]).powi(2) + (q[45] - q[43]).powi(2) - s0;
        g[23] = (q[46] - q[44]).powi(2) + (q[47] - q[45]).powi(2) - s0;
        g[24] = (q[48] - q[46]).powi(2) + (q[49] - q[47]).powi(2) - s0;
        g[25] = (q[50] - q[48]).powi(2) + (q[51] - q[49]).powi(2) - s0;
        g[26] = (q[52] - q[50]).powi(2) + (q[53] - q[51]).powi(2) - s0;
        g[27] = (q[54] - q[52]).powi(2) + (q[55] - q[53]).powi(2) - s0;
        g[28] = (q[56] - q[54]).powi(2) + (q[57] - q[55]).powi(2) - s0;
        g[29] = (q[58] - q[56]).powi(2) + (q[59] - q[57]).powi(2) - s0;
        g[30] = (q[60] - q[58]).powi(2) + (q[61] - q[59]).powi(2) - s0;
        g[31] = (q[62] - q[60]).powi(2) + (q[63] - q[61]).powi(2) - s0;
        g[32] = (q[64] - q[62]).powi(2) + (q[65] - q[63]).powi(2) - s0;
        g[33] = (q[66] - q[64]).powi(2) + (q[67] - q[65]).powi(2) - s0;
        g[34] = (q[68] - q[66]).powi(2) + (q[69] - q[67]).powi(2) - s0;
        g[35] = (q[70] - q[68]).powi(2) + (q[71] - q[69]).powi(2) - s0;
        g[36] = (q[72] - q[70]).powi(2) + (q[73] - q[71]).powi(2) - s0;
        g[37] = (q[74] - q[72]).powi(2) + (q[75] - q[73]).powi(2) - s0;
        g[38] = (q[76] - q[74]).powi(2) + (q[77] - q[75]).powi(2) - s0;
        g[39] = (q[78] - q[76]).powi(2) + (q[79] - q[77]).powi(2) - s0;
        g[40] = (q[80] - q[78]).powi(2) + (q[81] - q[79]).powi(2) - s0;
        g[41] = (q[82] - q[80]).powi(2) + (q[83] - q[81]).powi(2) - s0;
        g[42] = (q[84] - q[82]).powi(2) + (q[85] - q[83]).powi(2) - s0;
        g[43] = (q[86] - q[84]).powi(2) + (q[87] - q[85]).powi(2) - s0;
        g[44] = (q[88] - q[86]).powi(2) + (q[89] - q[87]).powi(2) - s0;
        g[45] = (q[90] - q[88]).powi(2) + (q[91] - q[89]).powi(2) - s0;
        g[46] = (q[92] - q[90]).powi(2) + (q[93] - q[91]).powi(2) - s0;
        g[47] = (q[94] - q[92]).powi(2) + (q[95] - q[93]).powi(2) - s0;
        g[48] = (q[96] - q[94]).powi(2) + (q[97] - q[95]).powi(2) - s0;
        g[49] = (q[98] - q[96]).powi(2) + (q[99] - q[97]).powi(2) - s0;
        g[50] = (q[100] - q[98]).powi(2) + (q[101] - q[99]).powi(2) - s0;
        g[51] = (q[102] - q[100]).powi(2) + (q[103] - q[101]).powi(2) - s0;
        g[52] = (q[104] - q[102]).powi(2) + (q[105] - q[103]).powi(2) - s0;
        g[53] = (q[106] - q[104]).powi(2) + (q[107] - q[105]).powi(2) - s0;
        g[54] = (q[108] - q[106]).powi(2) + (q[109] - q[107]).powi(2) - s0;
        g[55] = (q[110] - q[108]).powi(2) + (q[111] - q[109]).powi(2) - s0;
        g[56] = (q[112] - q[110]).powi(2) + (q[113] - q[111]).powi(2) - s0;
        g[57] = (q[114] - q[112]).powi(2) + (q[115] - q[113]).powi(2) - s0;
        g[58] = (q[116] - q[114]).powi(2) + (q[117] - q[115]).powi(2) - s0;
        g[59] = (q[118] - q[116]).powi(2) + (q[119] - q[117]).powi(2) - s0;
        g[60] = (q[120] - q[118]).powi(2) + (q[121] - q[119]).powi(2) - s0;
        g[61] = (q[122] - q[120]).powi(2) + (q[123] - q[121]).powi(2) - s0;
        g[62] = (q[124] - q[122]).powi(2) + (q[125] - q[123]).powi(2) - s0;
        g[63] = (q[126] - q[124]).powi(2) + (q[127] - q[125]).powi(2) - s0;
        g[64] = (q[128] - q[126]).powi(2) + (q[129] - q[127]).powi(2) - s0;
        g[65] = (q[130] - q[128]).powi(2) + (q[131] - q[129]).powi(2) - s0;
        g[66] = (q[132] - q[130]).powi(2) + (q[133] - q[131]).powi(2) - s0;
        g[67] = (q[134] - q[132]).powi(2) + (q[135] - q[133]).powi(2) - s0;
        g[68] = (q[136] - q[134]).powi(2) + (q[137] - q[135]).powi(2) - s0;
        g[69] = (q[138] - q[136]).powi(2) + (q[139] - q[137]).powi(2) - s0;
        g[70] = (q[140] - q[138]).powi(2) + (q[141] - q[139]).powi(2) - s0;
        g[71] = (q[142] - q[140]).powi(2) + (q[143] - q[141]).powi(2) - s0;
        g[72] = (q[144] - q[142]).powi(2) + (q[145] - q[143]).powi(2) - s0;
        g[73] = (q[146] - q[144]).powi(2) + (q[147] - q[145]).powi(2) - s0;
        g[74] = (q[148] - q[146]).powi(2) + (q[149] - q[147]).powi(2) - s0;
        g[75] = (q[150] - q[148]).powi(2) + (q[151] - q[149]).powi(2) - s0;
        g[76] = (q[152] - q[150]).powi(2) + (q[153] - q[151]).powi(2) - s0;
        g[77] = (q[154] - q[152]).powi(2) + (q[155] - q[153]).powi(2) - s0;
        g[78] = (q[156] - q[154]).powi(2) + (q[157] - q[155]).powi(2) - s0;
        g[79] = (q[158] - q[156]).powi(2) + (q[159] - q[157]).powi(2) - s0;
        g[80] = (q[160] - q[158]).powi(2) + (q[161] - q[159]).powi(2) - s0;
        g[81] = (q[162] - q[160]).powi(2) + (q[163] - q[161]).powi(2) - s0;
        g[82] = (q[164] - q[162]).powi(2) + (q[165] - q[163]).powi(2) - s0;
        g[83] = (q[166] - q[164]).powi(2) + (q[167] - q[165]).powi(2) - s0;
        g[84] = (q[168] - q[166]).powi(2) + (q[169] - q[167]).powi(2) - s0;
        g[85] = (q[170] - q[168]).powi(2) + (q[171] - q[169]).powi(2) - s0;
        g[86] = (q[172] - q[170]).powi(2) + (q[173] - q[171]).powi(2) - s0;
        g[87] = (q[174] - q[172]).powi(2) + (q[175] - q[173]).powi(2) - s0;
        g[88] = (q[176] - q[174]).powi(2) + (q[177] - q[175]).powi(2) - s0;
        g[89] = (q[178] - q[176]).powi(2) + (q[179] - q[177]).powi(2) - s0;
        g[90] = (q[180] - q[178]).powi(2) + (q[181] - q[179]).powi(2) - s0;
        g[91] = (q[182] - q[180]).powi(2) + (q[183] - q[181]).powi(2) - s0;
        g[92] = (q[184] - q[182]).powi(2) + (q[185] - q[183]).powi(2) - s0;
        g[93] = (q[186] - q[184]).powi(2) + (q[187] - q[185]).powi(2) - s0;
        g[94] = (q[188] - q[186]).powi(2) + (q[189] - q[187]).powi(2) - s0;
        g[95] = (q[190] - q[188]).powi(2) + (q[191] - q[189]).powi(2) - s0;
        g[96] = (q[192] - q[190]).powi(2) + (q[193] - q[191]).powi(2) - s0;
        g[97] = (q[194] - q[192]).powi(2) + (q[195] - q[193]).powi(2) - s0;
        g[98] = (q[196] - q[194]).powi(2) + (q[197] - q[195]).powi(2) - s0;
        g[99] = (q[198] - q[196]).powi(2) + (q[199] - q[197]).powi(2) - s0;
        g
    }
    #[inline]
    fn constraint_jacobian(
        &self,
        q: &::zeitner::__private::Vector<200>,
        v: &::zeitner::__private::Vector<200>,
        t: ::zeitner::__private::Float,
    ) -> ::zeitner::__private::Matrix<100, 200> {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let s0 = 2.0 * (q[2] - q[0]);
        let s1 = 2.0 * (q[3] - q[1]);
        let s2 = 2.0 * (q[4] - q[2]);
        let s3 = 2.0 * (q[5] - q[3]);
        let s4 = 2.0 * (q[6] - q[4]);
        let s5 = 2.0 * (q[7] - q[5]);
        let s6 = 2.0 * (q[8] - q[6]);
        let s7 = 2.0 * (q[9] - q[7]);
        let s8 = 2.0 * (q[10] - q[8]);
        let s9 = 2.0 * (q[11] - q[9]);
        let s10 = 2.0 * (q[12] - q[10]);
        let s11 = 2.0 * (q[13] - q[11]);
        let s12 = 2.0 * (q[14] - q[12]);
        let s13 = 2.0 * (q[15] - q[13]);
        let s14 = 2.0 * (q[16] - q[14]);
        let s15 = 2.0 * (q[17] - q[15]);
        let s16 = 2.0 * (q[18] - q[16]);
        let s17 = 2.0 * (q[19] - q[17]);
        let s18 = 2.0 * (q[20] - q[18]);
        let s19 = 2.0 * (q[21] - q[19]);
        let s20 = 2.0 * (q[22] - q[20]);
        let s21 = 2.0 * (q[23] - q[21]);
        let s22 = 2.0 * (q[24] - q[22]);
        let s23 = 2.0 * (q[25] - q[23]);
        let s24 = 2.0 * (q[26] - q[24]);
        let s25 = 2.0 * (q[27] - q[25]);
        let s26 = 2.0 * (q[28] - q[26]);
        let s27 = 2.0 * (q[29] - q[27]);
        let s28 = 2.0 * (q[30] - q[28]);
        let s29 = 2.0 * (q[31] - q[29]);
        let s30 = 2.0 * (q[32] - q[30]);
        let s31 = 2.0 * (q[33] - q[31]);
        let s32 = 2.0 * (q[34] - q[32]);
        let s33 = 2.0 * (q[35] - q[33]);
        let s34 = 2.0 * (q[36] - q[34]);
        let s35 = 2.0 * (q[37] - q[35]);
        let s36 = 2.0 * (q[38] - q[36]);
        let s37 = 2.0 * (q[39] - q[37]);
        let s38 = 2.0 * (q[40] - q[38]);
        let s39 = 2.0 * (q[41] - q[39]);
        let s40 = 2.0 * (q[42] - q[40]);
        let s41 = 2.0 * (q[43] - q[41]);
        let s42 = 2.0 * (q[44] - q[42]);
        let s43 = 2.0 * (q[45] - q[43]);
        let s44 = 2.0 * (q[46] - q[44]);
        let s45 = 2.0 * (q[47] - q[45]);
        let s46 = 2.0 * (q[48] - q[46]);
        let s47 = 2.0 * (q[49] - q[47]);
        let s48 = 2.0 * (q[50] - q[48]);
        let s49 = 2.0 * (q[51] - q[49]);
        let s50 = 2.0 * (q[52] - q[50]);
        let s51 = 2.0 * (q[53] - q[51]);
        let s52 = 2.0 * (q[54] - q[52]);
        let s53 = 2.0 * (q[55] - q[53]);
        let s54 = 2.0 * (q[56] - q[54]);
        let s55 = 2.0 * (q[57] - q[55]);
        let s56 = 2.0 * (q[58] - q[56]);
        let s57 = 2.0 * (q[59] - q[57]);
        let s58 = 2.0 * (q[60] - q[58]);
        let s59 = 2.0 * (q[61] - q[59]);
        let s60 = 2.0 * (q[62] - q[60]);
        let s61 = 2.0 * (q[63] - q[61]);
        let s62 = 2.0 * (q[64] - q[62]);
        let s63 = 2.0 * (q[65] - q[63]);
        let s64 = 2.0 * (q[66] - q[64]);
        let s65 = 2.0 * (q[67] - q[65]);
        let s66 = 2.0 * (q[68] - q[66]);
        let s67 = 2.0 * (q[69] - q[67]);
        let s68 = 2.0 * (q[70] - q[68]);
        let s69 = 2.0 * (q[71] - q[69]);
        let s70 = 2.0 * (q[72] - q[70]);
        let s71 = 2.0 * (q[73] - q[71]);
        let s72 = 2.0 * (q[74] - q[72]);
        let s73 = 2.0 * (q[75] - q[73]);
        let s74 = 2.0 * (q[76] - q[74]);
        let s75 = 2.0 * (q[77] - q[75]);
        let s76 = 2.0 * (q[78] - q[76]);
        let s77 = 2.0 * (q[79] - q[77]);
        let s78 = 2.0 * (q[80] - q[78]);
        let s79 = 2.0 * (q[81] - q[79]);
        let s80 = 2.0 * (q[82] - q[80]);
        let s81 = 2.0 * (q[83] - q[81]);
        let s82 = 2.0 * (q[84] - q[82]);
        let s83 = 2.0 * (q[85] - q[83]);
        let s84 = 2.0 * (q[86] - q[84]);
        let s85 = 2.0 * (q[87] - q[85]);
        let s86 = 2.0 * (q[88] - q[86]);
        let s87 = 2.0 * (q[89] - q[87]);
        let s88 = 2.0 * (q[90] - q[88]);
        let s89 = 2.0 * (q[91] - q[89]);
        let s90 = 2.0 * (q[92] - q[90]);
        let s91 = 2.0 * (q[93] - q[91]);
        let s92 = 2.0 * (q[94] - q[92]);
        let s93 = 2.0 * (q[95] - q[93]);
        let s94 = 2.0 * (q[96] - q[94]);
        let s95 = 2.0 * (q[97] - q[95]);
        let s96 = 2.0 * (q[98] - q[96]);
        let s97 = 2.0 * (q[99] - q[97]);
        let s98 = 2.0 * (q[100] - q[98]);
        let s99 = 2.0 * (q[101] - q[99]);
        let s100 = 2.0 * (q[102] - q[100]);
        let s101 = 2.0 * (q[103] - q[101]);
        let s102 = 2.0 * (q[104] - q[102]);
        let s103 = 2.0 * (q[105] - q[103]);
        let s104 = 2.0 * (q[106] - q[104]);
        let s105 = 2.0 * (q[107] - q[105]);
        let s106 = 2.0 * (q[108] - q[106]);
        let s107 = 2.0 * (q[109] - q[107]);
        let s108 = 2.0 * (q[110] - q[108]);
        let s109 = 2.0 * (q[111] - q[109]);
        let s110 = 2.0 * (q[112] - q[110]);
        let s111 = 2.0 * (q[113] - q[111]);
        let s112 = 2.0 * (q[114] - q[112]);
        let s113 = 2.0 * (q[115] - q[113]);
        let s114 = 2.0 * (q[116] - q[114]);
        let s115 = 2.0 * (q[117] - q[115]);
        let s116 = 2.0 * (q[118] - q[116]);
        let s117 = 2.0 * (q[119] - q[117]);
        let s118 = 2.0 * (q[120] - q[118]);
        let s119 = 2.0 * (q[121] - q[119]);
        let s120 = 2.0 * (q[122] - q[120]);
        let s121 = 2.0 * (q[123] - q[121]);
        let s122 = 2.0 * (q[124] - q[122]);
        let s123 = 2.0 * (q[125] - q[123]);
        let s124 = 2.0 * (q[126] - q[124]);
        let s125 = 2.0 * (q[127] - q[125]);
        let s126 = 2.0 * (q[128] - q[126]);
        let s127 = 2.0 * (q[129] - q[127]);
        let s128 = 2.0 * (q[130] - q[128]);
        let s129 = 2.0 * (q[131] - q[129]);
        let s130 = 2.0 * (q[132] - q[130]);
        let s131 = 2.0 * (q[133] - q[131]);
        let s132 = 2.0 * (q[134] - q[132]);
        let s133 = 2.0 * (q[135] - q[133]);
        let s134 = 2.0 * (q[136] - q[134]);
        let s135 = 2.0 * (q[137] - q[135]);
        let s136 = 2.0 * (q[138] - q[136]);
        let s137 = 2.0 * (q[139] - q[137]);
        let s138 = 2.0 * (q[140] - q[138]);
        let s139 = 2.0 * (q[141] - q[139]);
        let s140 = 2.0 * (q[142] - q[140]);
        let s141 = 2.0 * (q[143] - q[141]);
        let s142 = 2.0 * (q[144] - q[142]);
        let s143 = 2.0 * (q[145] - q[143]);
        let s144 = 2.0 * (q[146] - q[144]);
        let s145 = 2.0 * (q[147] - q[145]);
        let s146 = 2.0 * (q[148] - q[146]);
        let s147 = 2.0 * (q[149] - q[147]);
        let s148 = 2.0 * (q[150] - q[148]);
        let s149 = 2.0 * (q[151] - q[149]);
        let s150 = 2.0 * (q[152] - q[150]);
        let s151 = 2.0 * (q[153] - q[151]);
        let s152 = 2.0 * (q[154] - q[152]);
        let s153 = 2.0 * (q[155] - q[153]);
        let s154 = 2.0 * (q[156] - q[154]);
        let s155 = 2.0 * (q[157] - q[155]);
        let s156 = 2.0 * (q[158] - q[156]);
        let s157 = 2.0 * (q[159] - q[157]);
        let s158 = 2.0 * (q[160] - q[158]);
        let s159 = 2.0 * (q[161] - q[159]);
        let s160 = 2.0 * (q[162] - q[160]);
        let s161 = 2.0 * (q[163] - q[161]);
        let s162 = 2.0 * (q[164] - q[162]);
        let s163 = 2.0 * (q[165] - q[163]);
        let s164 = 2.0 * (q[166] - q[164]);
        let s165 = 2.0 * (q[167] - q[165]);
        let s166 = 2.0 * (q[168] - q[166]);
        let s167 = 2.0 * (q[169] - q[167]);
        let s168 = 2.0 * (q[170] - q[168]);
        let s169 = 2.0 * (q[171] - q[169]);
        let s170 = 2.0 * (q[172] - q[170]);
        let s171 = 2.0 * (q[173] - q[171]);
        let s172 = 2.0 * (q[174] - q[172]);
        let s173 = 2.0 * (q[175] - q[173]);
        let s174 = 2.0 * (q[176] - q[174]);
        let s175 = 2.0 * (q[177] - q[175]);
        let s176 = 2.0 * (q[178] - q[176]);
        let s177 = 2.0 * (q[179] - q[177]);
        let s178 = 2.0 * (q[180] - q[178]);
        let s179 = 2.0 * (q[181] - q[179]);
        let s180 = 2.0 * (q[182] - q[180]);
        let s181 = 2.0 * (q[183] - q[181]);
        let s182 = 2.0 * (q[184] - q[182]);
        let s183 = 2.0 * (q[185] - q[183]);
        let s184 = 2.0 * (q[186] - q[184]);
        let s185 = 2.0 * (q[187] - q[185]);
        let s186 = 2.0 * (q[188] - q[186]);
        let s187 = 2.0 * (q[189] - q[187]);
        let s188 = 2.0 * (q[190] - q[188]);
        let s189 = 2.0 * (q[191] - q[189]);
        let s190 = 2.0 * (q[192] - q[190]);
        let s191 = 2.0 * (q[193] - q[191]);
        let s192 = 2.0 * (q[194] - q[192]);
        let s193 = 2.0 * (q[195] - q[193]);
        let s194 = 2.0 * (q[196] - q[194]);
        let s195 = 2.0 * (q[197] - q[195]);
        let s196 = 2.0 * (q[198] - q[196]);
        let s197 = 2.0 * (q[199] - q[197]);
        let mut g = ::zeitner::__private::Matrix::<100, 200>::zeros();
        g[(0, 0)] = 2.0 * q[0];
        g[(0, 1)] = 2.0 * q[1];
        g[(1, 0)] = -s0;
        g[(1, 1)] = -s1;
        g[(1, 2)] = s0;
        g[(1, 3)] = s1;
        g[(2, 2)] = -s2;
        g[(2, 3)] = -s3;
        g[(2, 4)] = s2;
        g[(2, 5)] = s3;
        g[(3, 4)] = -s4;
        g[(3, 5)] = -s5;
        g[(3, 6)] = s4;
        g[(3, 7)] = s5;
        g[(4, 6)] = -s6;
        g[(4, 7)] = -s7;
        g[(4, 8)] = s6;
        g[(4, 9)] = s7;
        g[(5, 8)] = -s8;
        g[(5, 9)] = -s9;
        g[(5, 10)] = s8;
        g[(5, 11)] = s9;
        g[(6, 10)] = -s10;
        g[(6, 11)] = -s11;
        g[(6, 12)] = s10;
        g[(6, 13)] = s11;
        g[(7, 12)] = -s12;
        g[(7, 13)] = -s13;
        g[(7, 14)] = s12;
        g[(7, 15)] = s13;
        g[(8, 14)] = -s14;
        g[(8, 15)] = -s15;
        g[(8, 16)] = s14;
        g[(8, 17)] = s15;
        g[(9, 16)] = -s16;
        g[(9, 17)] = -s17;
        g[(9, 18)] = s16;
        g[(9, 19)] = s17;
        g[(10, 18)] = -s18;
        g[(10, 19)] = -s19;
        g[(10, 20)] = s18;
        g[(10, 21)] = s19;
        g[(11, 20)] = -s20;
        g[(11, 21)] = -s21;
        g[(11, 22)] = s20;
        g[(11, 23)] = s21;
        g[(12, 22)] = -s22;
        g[(12, 23)] = -s23;
        g[(12, 24)] = s22;
        g[(12, 25)] = s23;
        g[(13, 24)] = -s24;
        g[(13, 25)] = -s25;
        g[(13, 26)] = s24;
        g[(13, 27)] = s25;
        g[(14, 26)] = -s26;
        g[(14, 27)] = -s27;
        g[(14, 28)] = s26;
        g[(14, 29)] = s27;
        g[(15, 28)] = -s28;
        g[(15, 29)] = -s29;
        g[(15, 30)] = s28;
        g[(15, 31)] = s29;
        g[(16, 30)] = -s30;
        g[(16, 31)] = -s31;
        g[(16, 32)] = s30;
        g[(16, 33)] = s31;
        g[(17, 32)] = -s32;
        g[(17, 33)] = -s33;
        g[(17, 34)] = s32;
        g[(17, 35)] = s33;
        g[(18, 34)] = -s34;
        g[(18, 35)] = -s35;
        g[(18, 36)] = s34;
        g[(18, 37)] = s35;
        g[(19, 36)] = -s36;
        g[(19, 37)] = -s37;
        g[(19, 38)] = s36;
        g[(19, 39)] = s37;
        g[(20, 38)] = -s38;
        g[(20, 39)] = -s39;
        g[(20, 40)] = s38;
        g[(20, 41)] = s39;
        g[(21, 40)] = -s40;
        g[(21, 41)] = -s41;
        g[(21, 42)] = s40;
        g[(21, 43)] = s41;
        g[(22, 42)] = -s42;
        g[(22, 43)] = -s43;
        g[(22, 44)] = s42;
        g[(22, 45)] = s43;
        g[(23, 44)] = -s44;
        g[(23, 45)] = -s45;
        g[(23, 46)] = s44;
        g[(23, 47)] = s45;
        g[(24, 46)] = -s46;
        g[(24, 47)] = -s47;
        g[(24, 48)] = s46;
        g[(24, 49)] = s47;
        g[(25, 48)] = -s48;
        g[(25, 49)] = -s49;
        g[(25, 50)] = s48;
        g[(25, 51)] = s49;
        g[(26, 50)] = -s50;
        g[(26, 51)] = -s51;
        g[(26, 52)] = s50;
        g[(26, 53)] = s51;
        g[(27, 52)] = -s52;
        g[(27, 53)] = -s53;
        g[(27, 54)] = s52;
        g[(27, 55)] = s53;
        g[(28, 54)] = -s54;
        g[(28, 55)] = -s55;
        g[(28, 56)] = s54;
        g[(28, 57)] = s55;
        g[(29, 56)] = -s56;
        g[(29, 57)] = -s57;
        g[(29, 58)] = s56;
        g[(29, 59)] = s57;
        g[(30, 58)] = -s58;
        g[(30, 59)] = -s59;
        g[(30, 60)] = s58;
        g[(30, 61)] = s59;
        g[(31, 60)] = -s60;
        g[(31, 61)] = -s61;
        g[(31, 62)] = s60;
        g[(31, 63)] = s61;
        g[(32, 62)] = -s62;
        g[(32, 63)] = -s63;
        g[(32, 64)] = s62;
        g[(32, 65)] = s63;
        g[(33, 64)] = -s64;
        g[(33, 65)] = -s65;
        g[(33, 66)] = s64;
        g[(33, 67)] = s65;
        g[(34, 66)] = -s66;
        g[(34, 67)] = -s67;
        g[(34, 68)] = s66;
        g[(34, 69)] = s67;
        g[(35, 68)] = -s68;
        g[(35, 69)] = -s69;
        g[(35, 70)] = s68;
        g[(35, 71)] = s69;
        g[(36, 70)] = -s70;
        g[(36, 71)] = -s71;
        g[(36, 72)] = s70;
        g[(36, 73)] = s71;
        g[(37, 72)] = -s72;
        g[(37, 73)] = -s73;
        g[(37, 74)] = s72;
        g[(37, 75)] = s73;
        g[(38, 74)] = -s74;
        g[(38, 75)] = -s75;
        g[(38, 76)] = s74;
        g[(38, 77)] = s75;
        g[(39, 76)] = -s76;
        g[(39, 77)] = -s77;
        g[(39, 78)] = s76;
        g[(39, 79)] = s77;
        g[(40, 78)] = -s78;
        g[(40, 79)] = -s79;
        g[(40, 80)] = s78;
        g[(40, 81)] = s79;
        g[(41, 80)] = -s80;
        g[(41, 81)] = -s81;
        g[(41, 82)] = s80;
        g[(41, 83)] = s81;
        g[(42, 82)] = -s82;
        g[(42, 83)] = -s83;
        g[(42, 84)] = s82;
        g[(42, 85)] = s83;
        g[(43, 84)] = -s84;
        g[(43, 85)] = -s85;
        g[(43, 86)] = s84;
        g[(43, 87)] = s85;
        g[(44, 86)] = -s86;
        g[(44, 87)] = -s87;
        g[(44, 88)] = s86;
        g[(44, 89)] = s87;
        g[(45, 88)] = -s88;
        g[(45, 89)] = -s89;
        g[(45, 90)] = s88;
        g[(45, 91)] = s89;
        g[(46, 90)] = -s90;
        g[(46, 91)] = -s91;
        g[(46, 92)] = s90;
        g[(46, 93)] = s91;
        g[(47, 92)] = -s92;
        g[(47, 93)] = -s93;
        g[(47, 94)] = s92;
        g[(47, 95)] = s93;
        g[(48, 94)] = -s94;
        g[(48, 95)] = -s95;
        g[(48, 96)] = s94;
        g[(48, 97)] = s95;
        g[(49, 96)] = -s96;
        g[(49, 97)] = -s97;
        g[(49, 98)] = s96;
        g[(49, 99)] = s97;
        g[(50, 98)] = -s98;
        g[(50, 99)] = -s99;
        g[(50, 100)] = s98;
        g[(50, 101)] = s99;
        g[(51, 100)] = -s100;
        g[(51, 101)] = -s101;
        g[(51, 102)] = s100;
        g[(51, 103)] = s101;
        g[(52, 102)] = -s102;
        g[(52, 103)] = -s103;
        g[(52, 104)] = s102;
        g[(52, 105)] = s103;
        g[(53, 104)] = -s104;
        g[(53, 105)] = -s105;
        g[(53, 106)] = s104;
        g[(53, 107)] = s105;
        g[(54, 106)] = -s106;
        g[(54, 107)] = -s107;
        g[(54, 108)] = s106;
        g[(54, 109)] = s107;
        g[(55, 108)] = -s108;
        g[(55, 109)] = -s109;
        g[(55, 110)] = s108;
        g[(55, 111)] = s109;
        g[(56, 110)] = -s110;
        g[(56, 111)] = -s111;
        g[(56, 112)] = s110;
        g[(56, 113)] = s111;
        g[(57, 112)] = -s112;
        g[(57, 113)] = -s113;
        g[(57, 114)] = s112;
        g[(57, 115)] = s113;
        g[(58, 114)] = -s114;
        g[(58, 115)] = -s115;
        g[(58, 116)] = s114;
        g[(58, 117)] = s115;
        g[(59, 116)] = -s116;
        g[(59, 117)] = -s117;
        g[(59, 118)] = s116;
        g[(59, 119)] = s117;
        g[(60, 118)] = -s118;
        g[(60, 119)] = -s119;
        g[(60, 120)] = s118;
        g[(60, 121)] = s119;
        g[(61, 120)] = -s120;
        g[(61, 121)] = -s121;
        g[(61, 122)] = s120;
        g[(61, 123)] = s121;
        g[(62, 122)] = -s122;
        g[(62, 123)] = -s123;
        g[(62, 124)] = s122;
        g[(62, 125)] = s123;
        g[(63, 124)] = -s124;
        g[(63, 125)] = -s125;
        g[(63, 126)] = s124;
        g[(63, 127)] = s125;
        g[(64, 126)] = -s126;
        g[(64, 127)] = -s127;
        g[(64, 128)] = s126;
        g[(64, 129)] = s127;
        g[(65, 128)] = -s128;
        g[(65, 129)] = -s129;
        g[(65, 130)] = s128;
        g[(65, 131)] = s129;
        g[(66, 130)] = -s130;
        g[(66, 131)] = -s131;
        g[(66, 132)] = s130;
        g[(66, 133)] = s131;
        g[(67, 132)] = -s132;
        g[(67, 133)] = -s133;
        g[(67, 134)] = s132;
        g[(67, 135)] = s133;
        g[(68, 134)] = -s134;
        g[(68, 135)] = -s135;
        g[(68, 136)] = s134;
        g[(68, 137)] = s135;
        g[(69, 136)] = -s136;
        g[(69, 137)] = -s137;
        g[(69, 138)] = s136;
        g[(69, 139)] = s137;
        g[(70, 138)] = -s138;
        g[(70, 139)] = -s139;
        g[(70, 140)] = s138;
        g[(70, 141)] = s139;
        g[(71, 140)] = -s140;
        g[(71, 141)] = -s141;
        g[(71, 142)] = s140;
        g[(71, 143)] = s141;
        g[(72, 142)] = -s142;
        g[(72, 143)] = -s143;
        g[(72, 144)] = s142;
        g[(72, 145)] = s143;
        g[(73, 144)] = -s144;
        g[(73, 145)] = -s145;
        g[(73, 146)] = s144;
        g[(73, 147)] = s145;
        g[(74, 146)] = -s146;
        g[(74, 147)] = -s147;
        g[(74, 148)] = s146;
        g[(74, 149)] = s147;
        g[(75, 148)] = -s148;
        g[(75, 149)] = -s149;
        g[(75, 150)] = s148;
        g[(75, 151)] = s149;
        g[(76, 150)] = -s150;
        g[(76, 151)] = -s151;
        g[(76, 152)] = s150;
        g[(76, 153)] = s151;
        g[(77, 152)] = -s152;
        g[(77, 153)] = -s153;
        g[(77, 154)] = s152;
        g[(77, 155)] = s153;
        g[(78, 154)] = -s154;
        g[(78, 155)] = -s155;
        g[(78, 156)] = s154;
        g[(78, 157)] = s155;
        g[(79, 156)] = -s156;
        g[(79, 157)] = -s157;
        g[(79, 158)] = s156;
        g[(79, 159)] = s157;
        g[(80, 158)] = -s158;
        g[(80, 159)] = -s159;
        g[(80, 160)] = s158;
        g[(80, 161)] = s159;
        g[(81, 160)] = -s160;
        g[(81, 161)] = -s161;
        g[(81, 162)] = s160;
        g[(81, 163)] = s161;
        g[(82, 162)] = -s162;
        g[(82, 163)] = -s163;
        g[(82, 164)] = s162;
        g[(82, 165)] = s163;
        g[(83, 164)] = -s164;
        g[(83, 165)] = -s165;
        g[(83, 166)] = s164;
        g[(83, 167)] = s165;
        g[(84, 166)] = -s166;
        g[(84, 167)] = -s167;
        g[(84, 168)] = s166;
        g[(84, 169)] = s167;
        g[(85, 168)] = -s168;
        g[(85, 169)] = -s169;
        g[(85, 170)] = s168;
        g[(85, 171)] = s169;
        g[(86, 170)] = -s170;
        g[(86, 171)] = -s171;
        g[(86, 172)] = s170;
        g[(86, 173)] = s171;
        g[(87, 172)] = -s172;
        g[(87, 173)] = -s173;
        g[(87, 174)] = s172;
        g[(87, 175)] = s173;
        g[(88, 174)] = -s174;
        g[(88, 175)] = -s175;
        g[(88, 176)] = s174;
        g[(88, 177)] = s175;
        g[(89, 176)] = -s176;
        g[(89, 177)] = -s177;
        g[(89, 178)] = s176;
        g[(89, 179)] = s177;
        g[(90, 178)] = -s178;
        g[(90, 179)] = -s179;
        g[(90, 180)] = s178;
        g[(90, 181)] = s179;
        g[(91, 180)] = -s180;
        g[(91, 181)] = -s181;
        g[(91, 182)] = s180;
        g[(91, 183)] = s181;
        g[(92, 182)] = -s182;
        g[(92, 183)] = -s183;
        g[(92, 184)] = s182;
        g[(92, 185)] = s183;
        g[(93, 184)] = -s184;
        g[(93, 185)] = -s185;
        g[(93, 186)] = s184;
        g[(93, 187)] = s185;
        g[(94, 186)] = -s186;
        g[(94, 187)] = -s187;
        g[(94, 188)] = s186;
        g[(94, 189)] = s187;
        g[(95, 188)] = -s188;
        g[(95, 189)] = -s189;
        g[(95, 190)] = s188;
        g[(95, 191)] = s189;
        g[(96, 190)] = -s190;
        g[(96, 191)] = -s191;
        g[(96, 192)] = s190;
        g[(96, 193)] = s191;
        g[(97, 192)] = -s192;
        g[(97, 193)] = -s193;
        g[(97, 194)] = s192;
        g[(97, 195)] = s193;
        g[(98, 194)] = -s194;
        g[(98, 195)] = -s195;
        g[(98, 196)] = s194;
        g[(98, 197)] = s195;
        g[(99, 196)] = -s196;
        g[(99, 197)] = -s197;
        g[(99, 198)] = s196;
        g[(99, 199)] = s197;
        g
    }
    #[inline]
    fn constraint_rate(
        &self,
        q: &::zeitner::__private::Vector<200>,
        v: &::zeitner::__private::Vector<200>,
        t: ::zeitner::__private::Float,
    ) -> ::zeitner::__private::Vector<100> {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let s0 = 2.0 * (q[2] - q[0]);
        let s1 = 2.0 * (q[3] - q[1]);
        let s2 = 2.0 * (q[4] - q[2]);
        let s3 = 2.0 * (q[5] - q[3]);
        let s4 = 2.0 * (q[6] - q[4]);
        let s5 = 2.0 * (q[7] - q[5]);
        let s6 = 2.0 * (q[8] - q[6]);
        let s7 = 2.0 * (q[9] - q[7]);
        let s8 = 2.0 * (q[10] - q[8]);
        let s9 = 2.0 * (q[11] - q[9]);
        let s10 = 2.0 * (q[12] - q[10]);
        let s11 = 2.0 * (q[13] - q[11]);
        let s12 = 2.0 * (q[14] - q[12]);
        let s13 = 2.0 * (q[15] - q[13]);
        let s14 = 2.0 * (q[16] - q[14]);
        let s15 = 2.0 * (q[17] - q[15]);
        let s16 = 2.0 * (q[18] - q[16]);
        let s17 = 2.0 * (q[19] - q[17]);
        let s18 = 2.0 * (q[20] - q[18]);
        let s19 = 2.0 * (q[21] - q[19]);
        let s20 = 2.0 * (q[22] - q[20]);
        let s21 = 2.0 * (q[23] - q[21]);
        let s22 = 2.0 * (q[24] - q[22]);
        let s23 = 2.0 * (q[25] - q[23]);
        let s24 = 2.0 * (q[26] - q[24]);
        let s25 = 2.0 * (q[27] - q[25]);
        let s26 = 2.0 * (q[28] - q[26]);
        let s27 = 2.0 * (q[29] - q[27]);
        let s28 = 2.0 * (q[30] - q[28]);
        let s29 = 2.0 * (q[31] - q[29]);
        let s30 = 2.0 * (q[32] - q[30]);
        let s31 = 2.0 * (q[33] - q[31]);
        let s32 = 2.0 * (q[34] - q[32]);
        let s33 = 2.0 * (q[35] - q[33]);
        let s34 = 2.0 * (q[36] - q[34]);
        let s35 = 2.0 * (q[37] - q[35]);
        let s36 = 2.0 * (q[38] - q[36]);
        let s37 = 2.0 * (q[39] - q[37]);
        let s38 = 2.0 * (q[40] - q[38]);
        let s39 = 2.0 * (q[41] - q[39]);
        let s40 = 2.0 * (q[42] - q[40]);
        let s41 = 2.0 * (q[43] - q[41]);
        let s42 = 2.0 * (q[44] - q[42]);
        let s43 = 2.0 * (q[45] - q[43]);
        let s44 = 2.0 * (q[46] - q[44]);
        let s45 = 2.0 * (q[47] - q[45]);
        let s46 = 2.0 * (q[48] - q[46]);
        let s47 = 2.0 * (q[49] - q[47]);
        let s48 = 2.0 * (q[50] - q[48]);
        let s49 = 2.0 * (q[51] - q[49]);
        let s50 = 2.0 * (q[52] - q[50]);
        let s51 = 2.0 * (q[53] - q[51]);
        let s52 = 2.0 * (q[54] - q[52]);
        let s53 = 2.0 * (q[55] - q[53]);
        let s54 = 2.0 * (q[56] - q[54]);
        let s55 = 2.0 * (q[57] - q[55]);
        let s56 = 2.0 * (q[58] - q[56]);
        let s57 = 2.0 * (q[59] - q[57]);
        let s58 = 2.0 * (q[60] - q[58]);
        let s59 = 2.0 * (q[61] - q[59]);
        let s60 = 2.0 * (q[62] - q[60]);
        let s61 = 2.0 * (q[63] - q[61]);
        let s62 = 2.0 * (q[64] - q[62]);
        let s63 = 2.0 * (q[65] - q[63]);
        let s64 = 2.0 * (q[66] - q[64]);
        let s65 = 2.0 * (q[67] - q[65]);
        let s66 = 2.0 * (q[68] - q[66]);
        let s67 = 2.0 * (q[69] - q[67]);
        let s68 = 2.0 * (q[70] - q[68]);
        let s69 = 2.0 * (q[71] - q[69]);
        let s70 = 2.0 * (q[72] - q[70]);
        let s71 = 2.0 * (q[73] - q[71]);
        let s72 = 2.0 * (q[74] - q[72]);
        let s73 = 2.0 * (q[75] - q[73]);
        let s74 = 2.0 * (q[76] - q[74]);
        let s75 = 2.0 * (q[77] - q[75]);
        let s76 = 2.0 * (q[78] - q[76]);
        let s77 = 2.0 * (q[79] - q[77]);
        let s78 = 2.0 * (q[80] - q[78]);
        let s79 = 2.0 * (q[81] - q[79]);
        let s80 = 2.0 * (q[82] - q[80]);
        let s81 = 2.0 * (q[83] - q[81]);
        let s82 = 2.0 * (q[84] - q[82]);
        let s83 = 2.0 * (q[85] - q[83]);
        let s84 = 2.0 * (q[86] - q[84]);
        let s85 = 2.0 * (q[87] - q[85]);
        let s86 = 2.0 * (q[88] - q[86]);
        let s87 = 2.0 * (q[89] - q[87]);
        let s88 = 2.0 * (q[90] - q[88]);
        let s89 = 2.0 * (q[91] - q[89]);
        let s90 = 2.0 * (q[92] - q[90]);
        let s91 = 2.0 * (q[93] - q[91]);
        let s92 = 2.0 * (q[94] - q[92]);
        let s93 = 2.0 * (q[95] - q[93]);
        let s94 = 2.0 * (q[96] - q[94]);
        let s95 = 2.0 * (q[97] - q[95]);
        let s96 = 2.0 * (q[98] - q[96]);
        let s97 = 2.0 * (q[99] - q[97]);
        let s98 = 2.0 * (q[100] - q[98]);
        let s99 = 2.0 * (q[101] - q[99]);
        let s100 = 2.0 * (q[102] - q[100]);
        let s101 = 2.0 * (q[103] - q[101]);
        let s102 = 2.0 * (q[104] - q[102]);
        let s103 = 2.0 * (q[105] - q[103]);
        let s104 = 2.0 * (q[106] - q[104]);
        let s105 = 2.0 * (q[107] - q[105]);
        let s106 = 2.0 * (q[108] - q[106]);
        let s107 = 2.0 * (q[109] - q[107]);
        let s108 = 2.0 * (q[110] - q[108]);
        let s109 = 2.0 * (q[111] - q[109]);
        let s110 = 2.0 * (q[112] - q[110]);
        let s111 = 2.0 * (q[113] - q[111]);
        let s112 = 2.0 * (q[114] - q[112]);
        let s113 = 2.0 * (q[115] - q[113]);
        let s114 = 2.0 * (q[116] - q[114]);
        let s115 = 2.0 * (q[117] - q[115]);
        let s116 = 2.0 * (q[118] - q[116]);
        let s117 = 2.0 * (q[119] - q[117]);
        let s118 = 2.0 * (q[120] - q[118]);
        let s119 = 2.0 * (q[121] - q[119]);
        let s120 = 2.0 * (q[122] - q[120]);
        let s121 = 2.0 * (q[123] - q[121]);
        let s122 = 2.0 * (q[124] - q[122]);
        let s123 = 2.0 * (q[125] - q[123]);
        let s124 = 2.0 * (q[126] - q[124]);
        let s125 = 2.0 * (q[127] - q[125]);
        let s126 = 2.0 * (q[128] - q[126]);
        let s127 = 2.0 * (q[129] - q[127]);
        let s128 = 2.0 * (q[130] - q[128]);
        let s129 = 2.0 * (q[131] - q[129]);
        let s130 = 2.0 * (q[132] - q[130]);
        let s131 = 2.0 * (q[133] - q[131]);
        let s132 = 2.0 * (q[134] - q[132]);
        let s133 = 2.0 * (q[135] - q[133]);
        let s134 = 2.0 * (q[136] - q[134]);
        let s135 = 2.0 * (q[137] - q[135]);
        let s136 = 2.0 * (q[138] - q[136]);
        let s137 = 2.0 * (q[139] - q[137]);
        let s138 = 2.0 * (q[140] - q[138]);
        let s139 = 2.0 * (q[141] - q[139]);
        let s140 = 2.0 * (q[142] - q[140]);
        let s141 = 2.0 * (q[143] - q[141]);
        let s142 = 2.0 * (q[144] - q[142]);
        let s143 = 2.0 * (q[145] - q[143]);
        let s144 = 2.0 * (q[146] - q[144]);
        let s145 = 2.0 * (q[147] - q[145]);
        let s146 = 2.0 * (q[148] - q[146]);
        let s147 = 2.0 * (q[149] - q[147]);
        let s148 = 2.0 * (q[150] - q[148]);
        let s149 = 2.0 * (q[151] - q[149]);
        let s150 = 2.0 * (q[152] - q[150]);
        let s151 = 2.0 * (q[153] - q[151]);
        let s152 = 2.0 * (q[154] - q[152]);
        let s153 = 2.0 * (q[155] - q[153]);
        let s154 = 2.0 * (q[156] - q[154]);
        let s155 = 2.0 * (q[157] - q[155]);
        let s156 = 2.0 * (q[158] - q[156]);
        let s157 = 2.0 * (q[159] - q[157]);
        let s158 = 2.0 * (q[160] - q[158]);
        let s159 = 2.0 * (q[161] - q[159]);
        let s160 = 2.0 * (q[162] - q[160]);
        let s161 = 2.0 * (q[163] - q[161]);
        let s162 = 2.0 * (q[164] - q[162]);
        let s163 = 2.0 * (q[165] - q[163]);
        let s164 = 2.0 * (q[166] - q[164]);
        let s165 = 2.0 * (q[167] - q[165]);
        let s166 = 2.0 * (q[168] - q[166]);
        let s167 = 2.0 * (q[169] - q[167]);
        let s168 = 2.0 * (q[170] - q[168]);
        let s169 = 2.0 * (q[171] - q[169]);
        let s170 = 2.0 * (q[172] - q[170]);
        let s171 = 2.0 * (q[173] - q[171]);
        let s172 = 2.0 * (q[174] - q[172]);
        let s173 = 2.0 * (q[175] - q[173]);
        let s174 = 2.0 * (q[176] - q[174]);
        let s175 = 2.0 * (q[177] - q[175]);
        let s176 = 2.0 * (q[178] - q[176]);
        let s177 = 2.0 * (q[179] - q[177]);
        let s178 = 2.0 * (q[180] - q[178]);
        let s179 = 2.0 * (q[181] - q[179]);
        let s180 = 2.0 * (q[182] - q[180]);
        let s181 = 2.0 * (q[183] - q[181]);
        let s182 = 2.0 * (q[184] - q[182]);
        let s183 = 2.0 * (q[185] - q[183]);
        let s184 = 2.0 * (q[186] - q[184]);
        let s185 = 2.0 * (q[187] - q[185]);
        let s186 = 2.0 * (q[188] - q[186]);
        let s187 = 2.0 * (q[189] - q[187]);
        let s188 = 2.0 * (q[190] - q[188]);
        let s189 = 2.0 * (q[191] - q[189]);
        let s190 = 2.0 * (q[192] - q[190]);
        let s191 = 2.0 * (q[193] - q[191]);
        let s192 = 2.0 * (q[194] - q[192]);
        let s193 = 2.0 * (q[195] - q[193]);
        let s194 = 2.0 * (q[196] - q[194]);
        let s195 = 2.0 * (q[197] - q[195]);
        let s196 = 2.0 * (q[198] - q[196]);
        let s197 = 2.0 * (q[199] - q[197]);
        let mut w = ::zeitner::__private::Vector::<100>::zeros();
        w[0] = 2.0 * q[0] * v[0] + 2.0 * q[1] * v[1];
        w[1] = -(s0 * v[0]) - s1 * v[1] + s0 * v[2] + s1 * v[3];
        w[2] = -(s2 * v[2]) - s3 * v[3] + s2 * v[4] + s3 * v[5];
        w[3] = -(s4 * v[4]) - s5 * v[5] + s4 * v[6] + s5 * v[7];
        w[4] = -(s6 * v[6]) - s7 * v[7] + s6 * v[8] + s7 * v[9];
        w[5] = -(s8 * v[8]) - s9 * v[9] + s8 * v[10] + s9 * v[11];
        w[6] = -(s10 * v[10]) - s11 * v[11] + s10 * v[12] + s11 * v[13];
        w[7] = -(s12 * v[12]) - s13 * v[13] + s12 * v[14] + s13 * v[15];
        w[8] = -(s14 * v[14]) - s15 * v[15] + s14 * v[16] + s15 * v[17];
        w[9] = -(s16 * v[16]) - s17 * v[17] + s16 * v[18] + s17 * v[19];
        w[10] = -(s18 * v[18]) - s19 * v[19] + s18 * v[20] + s19 * v[21];
        w[11] = -(s20 * v[20]) - s21 * v[21] + s20 * v[22] + s21 * v[23];
        w[12] = -(s22 * v[22]) - s23 * v[23] + s22 * v[24] + s23 * v[25];
        w[13] = -(s24 * v[24]) - s25 * v[25] + s24 * v[26] + s25 * v[27];
        w[14] = -(s26 * v[26]) - s27 * v[27] + s26 * v[28] + s27 * v[29];
        w[15] = -(s28 * v[28]) - s29 * v[29] + s28 * v[30] + s29 * v[31];
        w[16] = -(s30 * v[30]) - s31 * v[31] + s30 * v[32] + s31 * v[33];
        w[17] = -(s32 * v[32]) - s33 * v[33] + s32 * v[34] + s33 * v[35];
        w[18] = -(s34 * v[34]) - s35 * v[35] + s34 * v[36] + s35 * v[37];
        w[19] = -(s36 * v[36]) - s37 * v[37] + s36 * v[38] + s37 * v[39];
        w[20] = -(s38 * v[38]) - s39 * v[39] + s38 * v[40] + s39 * v[41];
        w[21] = -(s40 * v[40]) - s41 * v[41] + s40 * v[42] + s41 * v[43];
        w[22] = -(s42 * v[42]) - s43 * v[43] + s42 * v[44] + s43 * v[45];
        w[23] = -(s44 * v[44]) - s45 * v[45] + s44 * v[46] + s45 * v[47];
        w[24] = -(s46 * v[46]) - s47 * v[47] + s46 * v[48] + s47 * v[49];
        w[25] = -(s48 * v[48]) - s49 * v[49] + s48 * v[50] + s49 * v[51];
        w[26] = -(s50 * v[50]) - s51 * v[51] + s50 * v[52] + s51 * v[53];
        w[27] = -(s52 * v[52]) - s53 * v[53] + s52 * v[54] + s53 * v[55];
        w[28] = -(s54 * v[54]) - s55 * v[55] + s54 * v[56] + s55 * v[57];
        w[29] = -(s56 * v[56]) - s57 * v[57] + s56 * v[58] + s57 * v[59];
        w[30] = -(s58 * v[58]) - s59 * v[59] + s58 * v[60] + s59 * v[61];
        w[31] = -(s60 * v[60]) - s61 * v[61] + s60 * v[62] + s61 * v[63];
        w[32] = -(s62 * v[62]) - s63 * v[63] + s62 * v[64] + s63 * v[65];
        w[33] = -(s64 * v[64]) - s65 * v[65] + s64 * v[66] + s65 * v[67];
        w[34] = -(s66 * v[66]) - s67 * v[67] + s66 * v[68] + s67 * v[69];
        w[35] = -(s68 * v[68]) - s69 * v[69] + s68 * v[70] + s69 * v[71];
        w[36] = -(s70 * v[70]) - s71 * v[71] + s70 * v[72] + s71 * v[73];
        w[37] = -(s72 * v[72]) - s73 * v[73] + s72 * v[74] + s73 * v[75];
        w[38] = -(s74 * v[74]) - s75 * v[75] + s74 * v[76] + s75 * v[77];
        w[39] = -(s76 * v[76]) - s77 * v[77] + s76 * v[78] + s77 * v[79];
        w[40] = -(s78 * v[78]) - s79 * v[79] + s78 * v[80] + s79 * v[81];
        w[41] = -(s80 * v[80]) - s81 * v[81] + s80 * v[82] + s81 * v[83];
        w[42] = -(s82 * v[82]) - s83 * v[83] + s82 * v[84] + s83 * v[85];
        w[43] = -(s84 * v[84]) - s85 * v[85] + s84 * v[86] + s85 * v[87];
        w[44] = -(s86 * v[86]) - s87 * v[87] + s86 * v[88] + s87 * v[89];
        w[45] = -(s88 * v[88]) - s89 * v[89] + s88 * v[90] + s89 * v[91];
        w[46] = -(s90 * v[90]) - s91 * v[91] + s90 * v[92] + s91 * v[93];
        w[47] = -(s92 * v[92]) - s93 * v[93] + s92 * v[94] + s93 * v[95];
        w[48] = -(s94 * v[94]) - s95 * v[95] + s94 * v[96] + s95 * v[97];
        w[49] = -(s96 * v[96]) - s97 * v[97] + s96 * v[98] + s97 * v[99];
        w[50] = -(s98 * v[98]) - s99 * v[99] + s98 * v[100] + s99 * v[101];
        w[51] = -(s100 * v[100]) - s101 * v[101] + s100 * v[102] + s101 * v[103];
        w[52] = -(s102 * v[102]) - s103 * v[103] + s102 * v[104] + s103 * v[105];
        w[53] = -(s104 * v[104]) - s105 * v[105] + s104 * v[106] + s105 * v[107];
        w[54] = -(s106 * v[106]) - s107 * v[107] + s106 * v[108] + s107 * v[109];
        w[55] = -(s108 * v[108]) - s109 * v[109] + s108 * v[110] + s109 * v[111];
        w[56] = -(s110 * v[110]) - s111 * v[111] + s110 * v[112] + s111 * v[113];
        w[57] = -(s112 * v[112]) - s113 * v[113] + s112 * v[114] + s113 * v[115];
        w[58] = -(s114 * v[114]) - s115 * v[115] + s114 * v[116] + s115 * v[117];
        w[59] = -(s116 * v[116]) - s117 * v[117] + s116 * v[118] + s117 * v[119];
        w[60] = -(s118 * v[118]) - s119 * v[119] + s118 * v[120] + s119 * v[121];
        w[61] = -(s120 * v[120]) - s121 * v[121] + s120 * v[122] + s121 * v[123];
        w[62] = -(s122 * v[122]) - s123 * v[123] + s122 * v[124] + s123 * v[125];
        w[63] = -(s124 * v[124]) - s125 * v[125] + s124 * v[126] + s125 * v[127];
        w[64] = -(s126 * v[126]) - s127 * v[127] + s126 * v[128] + s127 * v[129];
        w[65] = -(s128 * v[128]) - s129 * v[129] + s128 * v[130] + s129 * v[131];
        w[66] = -(s130 * v[130]) - s131 * v[131] + s130 * v[132] + s131 * v[133];
        w[67] = -(s132 * v[132]) - s133 * v[133] + s132 * v[134] + s133 * v[135];
        w[68] = -(s134 * v[134]) - s135 * v[135] + s134 * v[136] + s135 * v[137];
        w[69] = -(s136 * v[136]) - s137 * v[137] + s136 * v[138] + s137 * v[139];
        w[70] = -(s138 * v[138]) - s139 * v[139] + s138 * v[140] + s139 * v[141];
        w[71] = -(s140 * v[140]) - s141 * v[141] + s140 * v[142] + s141 * v[143];
        w[72] = -(s142 * v[142]) - s143 * v[143] + s142 * v[144] + s143 * v[145];
        w[73] = -(s144 * v[144]) - s145 * v[145] + s144 * v[146] + s145 * v[147];
        w[74] = -(s146 * v[146]) - s147 * v[147] + s146 * v[148] + s147 * v[149];
        w[75] = -(s148 * v[148]) - s149 * v[149] + s148 * v[150] + s149 * v[151];
        w[76] = -(s150 * v[150]) - s151 * v[151] + s150 * v[152] + s151 * v[153];
        w[77] = -(s152 * v[152]) - s153 * v[153] + s152 * v[154] + s153 * v[155];
        w[78] = -(s154 * v[154]) - s155 * v[155] + s154 * v[156] + s155 * v[157];
        w[79] = -(s156 * v[156]) - s157 * v[157] + s156 * v[158] + s157 * v[159];
        w[80] = -(s158 * v[158]) - s159 * v[159] + s158 * v[160] + s159 * v[161];
        w[81] = -(s160 * v[160]) - s161 * v[161] + s160 * v[162] + s161 * v[163];
        w[82] = -(s162 * v[162]) - s163 * v[163] + s162 * v[164] + s163 * v[165];
        w[83] = -(s164 * v[164]) - s165 * v[165] + s164 * v[166] + s165 * v[167];
        w[84] = -(s166 * v[166]) - s167 * v[167] + s166 * v[168] + s167 * v[169];
        w[85] = -(s168 * v[168]) - s169 * v[169] + s168 * v[170] + s169 * v[171];
        w[86] = -(s170 * v[170]) - s171 * v[171] + s170 * v[172] + s171 * v[173];
        w[87] = -(s172 * v[172]) - s173 * v[173] + s172 * v[174] + s173 * v[175];
        w[88] = -(s174 * v[174]) - s175 * v[175] + s174 * v[176] + s175 * v[177];
        w[89] = -(s176 * v[176]) - s177 * v[177] + s176 * v[178] + s177 * v[179];
        w[90] = -(s178 * v[178]) - s179 * v[179] + s178 * v[180] + s179 * v[181];
        w[91] = -(s180 * v[180]) - s181 * v[181] + s180 * v[182] + s181 * v[183];
        w[92] = -(s182 * v[182]) - s183 * v[183] + s182 * v[184] + s183 * v[185];
        w[93] = -(s184 * v[184]) - s185 * v[185] + s184 * v[186] + s185 * v[187];
        w[94] = -(s186 * v[186]) - s187 * v[187] + s186 * v[188] + s187 * v[189];
        w[95] = -(s188 * v[188]) - s189 * v[189] + s188 * v[190] + s189 * v[191];
        w[96] = -(s190 * v[190]) - s191 * v[191] + s190 * v[192] + s191 * v[193];
        w[97] = -(s192 * v[192]) - s193 * v[193] + s192 * v[194] + s193 * v[195];
        w[98] = -(s194 * v[194]) - s195 * v[195] + s194 * v[196] + s195 * v[197];
        w[99] = -(s196 * v[196]) - s197 * v[197] + s196 * v[198] + s197 * v[199];
        w
    }
    #[inline]
    fn constraint_acceleration_bias(
        &self,
        q: &::zeitner::__private::Vector<200>,
        v: &::zeitner::__private::Vector<200>,
        t: ::zeitner::__private::Float,
    ) -> ::zeitner::__private::Vector<100> {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let s0 = 2.0 * v[0];
        let s1 = 2.0 * v[1];
        let s2 = -2.0 * v[2];
        let s3 = -2.0 * v[3];
        let s4 = 2.0 * v[2];
        let s5 = 2.0 * v[3];
        let s6 = -2.0 * v[4];
        let s7 = -2.0 * v[5];
        let s8 = 2.0 * v[4];
        let s9 = 2.0 * v[5];
        let s10 = -2.0 * v[6];
        let s11 = -2.0 * v[7];
        let s12 = 2.0 * v[6];
        let s13 = 2.0 * v[7];
        let s14 = -2.0 * v[8];
        let s15 = -2.0 * v[9];
        let s16 = 2.0 * v[8];
        let s17 = 2.0 * v[9];
        let s18 = -2.0 * v[10];
        let s19 = -2.0 * v[11];
        let s20 = 2.0 * v[10];
        let s21 = 2.0 * v[11];
        let s22 = -2.0 * v[12];
        let s23 = -2.0 * v[13];
        let s24 = 2.0 * v[12];
        let s25 = 2.0 * v[13];
        let s26 = -2.0 * v[14];
        let s27 = -2.0 * v[15];
        let s28 = 2.0 * v[14];
        let s29 = 2.0 * v[15];
        let s30 = -2.0 * v[16];
        let s31 = -2.0 * v[17];
        let s32 = 2.0 * v[16];
        let s33 = 2.0 * v[17];
        let s34 = -2.0 * v[18];
        let s35 = -2.0 * v[19];
        let s36 = 2.0 * v[18];
        let s37 = 2.0 * v[19];
        let s38 = -2.0 * v[20];
        let s39 = -2.0 * v[21];
        let s40 = 2.0 * v[20];
        let s41 = 2.0 * v[21];
        let s42 = -2.0 * v[22];
        let s43 = -2.0 * v[23];
        let s44 = 2.0 * v[22];
        let s45 = 2.0 * v[23];
        let s46 = -2.0 * v[24];
        let s47 = -2.0 * v[25];
        let s48 = 2.0 * v[24];
        let s49 = 2.0 * v[25];
        let s50 = -2.0 * v[26];
        let s51 = -2.0 * v[27];
        let s52 = 2.0 * v[26];
        let s53 = 2.0 * v[27];
        let s54 = -2.0 * v[28];
        let s55 = -2.0 * v[29];
        let s56 = 2.0 * v[28];
        let s57 = 2.0 * v[29];
        let s58 = -2.0 * v[30];
        let s59 = -2.0 * v[31];
        let s60 = 2.0 * v[30];
        let s61 = 2.0 * v[31];
        let s62 = -2.0 * v[32];
        let s63 = -2.0 * v[33];
        let s64 = 2.0 * v[32];
        let s65 = 2.0 * v[33];
        let s66 = -2.0 * v[34];
        let s67 = -2.0 * v[35];
        let s68 = 2.0 * v[34];
        let s69 = 2.0 * v[35];
        let s70 = -2.0 * v[36];
        let s71 = -2.0 * v[37];
        let s72 = 2.0 * v[36];
        let s73 = 2.0 * v[37];
        let s74 = -2.0 * v[38];
        let s75 = -2.0 * v[39];
        let s76 = 2.0 * v[38];
        let s77 = 2.0 * v[39];
        let s78 = -2.0 * v[40];
        let s79 = -2.0 * v[41];
        let s80 = 2.0 * v[40];
        let s81 = 2.0 * v[41];
        let s82 = -2.0 * v[42];
        let s83 = -2.0 * v[43];
        let s84 = 2.0 * v[42];
        let s85 = 2.0 * v[43];
        let s86 = -2.0 * v[44];
        let s87 = -2.0 * v[45];
        let s88 = 2.0 * v[44];
        let s89 = 2.0 * v[45];
        let s90 = -2.0 * v[46];
        let s91 = -2.0 * v[47];
        let s92 = 2.0 * v[46];
        let s93 = 2.0 * v[47];
        let s94 = -2.0 * v[48];
        let s95 = -2.0 * v[49];
        let s96 = 2.0 * v[48];
        let s97 = 2.0 * v[49];
        let s98 = -2.0 * v[50];
        let s99 = -2.0 * v[51];
        let s100 = 2.0 * v[50];
        let s101 = 2.0 * v[51];
        let s102 = -2.0 * v[52];
        let s103 = -2.0 * v[53];
        let s104 = 2.0 * v[52];
        let s105 = 2.0 * v[53];
        let s106 = -2.0 * v[54];
        let s107 = -2.0 * v[55];
        let s108 = 2.0 * v[54];
        let s109 = 2.0 * v[55];
        let s110 = -2.0 * v[56];
        let s111 = -2.0 * v[57];
        let s112 = 2.0 * v[56];
        let s113 = 2.0 * v[57];
        let s114 = -2.0 * v[58];
        let s115 = -2.0 * v[59];
        let s116 = 2.0 * v[58];
        let s117 = 2.0 * v[59];
        let s118 = -2.0 * v[60];
        let s119 = -2.0 * v[61];
        let s120 = 2.0 * v[60];
        let s121 = 2.0 * v[61];
        let s122 = -2.0 * v[62];
        let s123 = -2.0 * v[63];
        let s124 = 2.0 * v[62];
        let s125 = 2.0 * v[63];
        let s126 = -2.0 * v[64];
        let s127 = -2.0 * v[65];
        let s128 = 2.0 * v[64];
        let s129 = 2.0 * v[65];
        let s130 = -2.0 * v[66];
        let s131 = -2.0 * v[67];
        let s132 = 2.0 * v[66];
        let s133 = 2.0 * v[67];
        let s134 = -2.0 * v[68];
        let s135 = -2.0 * v[69];
        let s136 = 2.0 * v[68];
        let s137 = 2.0 * v[69];
        let s138 = -2.0 * v[70];
        let s139 = -2.0 * v[71];
        let s140 = 2.0 * v[70];
        let s141 = 2.0 * v[71];
        let s142 = -2.0 * v[72];
        let s143 = -2.0 * v[73];
        let s144 = 2.0 * v[72];
        let s145 = 2.0 * v[73];
        let s146 = -2.0 * v[74];
        let s147 = -2.0 * v[75];
        let s148 = 2.0 * v[74];
        let s149 = 2.0 * v[75];
        let s150 = -2.0 * v[76];
        let s151 = -2.0 * v[77];
        let s152 = 2.0 * v[76];
        let s153 = 2.0 * v[77];
        let s154 = -2.0 * v[78];
        let s155 = -2.0 * v[79];
        let s156 = 2.0 * v[78];
        let s157 = 2.0 * v[79];
        let s158 = -2.0 * v[80];
        let s159 = -2.0 * v[81];
        let s160 = 2.0 * v[80];
        let s161 = 2.0 * v[81];
        let s162 = -2.0 * v[82];
        let s163 = -2.0 * v[83];
        let s164 = 2.0 * v[82];
        let s165 = 2.0 * v[83];
        let s166 = -2.0 * v[84];
        let s167 = -2.0 * v[85];
        let s168 = 2.0 * v[84];
        let s169 = 2.0 * v[85];
        let s170 = -2.0 * v[86];
        let s171 = -2.0 * v[87];
        let s172 = 2.0 * v[86];
        let s173 = 2.0 * v[87];
        let s174 = -2.0 * v[88];
        let s175 = -2.0 * v[89];
        let s176 = 2.0 * v[88];
        let s177 = 2.0 * v[89];
        let s178 = -2.0 * v[90];
        let s179 = -2.0 * v[91];
        let s180 = 2.0 * v[90];
        let s181 = 2.0 * v[91];
        let s182 = -2.0 * v[92];
        let s183 = -2.0 * v[93];
        let s184 = 2.0 * v[92];
        let s185 = 2.0 * v[93];
        let s186 = -2.0 * v[94];
        let s187 = -2.0 * v[95];
        let s188 = 2.0 * v[94];
        let s189 = 2.0 * v[95];
        let s190 = -2.0 * v[96];
        let s191 = -2.0 * v[97];
        let s192 = 2.0 * v[96];
        let s193 = 2.0 * v[97];
        let s194 = -2.0 * v[98];
        let s195 = -2.0 * v[99];
        let s196 = 2.0 * v[98];
        let s197 = 2.0 * v[99];
        let s198 = -2.0 * v[100];
        let s199 = -2.0 * v[101];
        let s200 = 2.0 * v[100];
        let s201 = 2.0 * v[101];
        let s202 = -2.0 * v[102];
        let s203 = -2.0 * v[103];
        let s204 = 2.0 * v[102];
        let s205 = 2.0 * v[103];
        let s206 = -2.0 * v[104];
        let s207 = -2.0 * v[105];
        let s208 = 2.0 * v[104];
        let s209 = 2.0 * v[105];
        let s210 = -2.0 * v[106];
        let s211 = -2.0 * v[107];
        let s212 = 2.0 * v[106];
        let s213 = 2.0 * v[107];
        let s214 = -2.0 * v[108];
        let s215 = -2.0 * v[109];
        let s216 = 2.0 * v[108];
        let s217 = 2.0 * v[109];
        let s218 = -2.0 * v[110];
        let s219 = -2.0 * v[111];
        let s220 = 2.0 * v[110];
        let s221 = 2.0 * v[111];
        let s222 = -2.0 * v[112];
        let s223 = -2.0 * v[113];
        let s224 = 2.0 * v[112];
        let s225 = 2.0 * v[113];
        let s226 = -2.0 * v[114];
        let s227 = -2.0 * v[115];
        let s228 = 2.0 * v[114];
        let s229 = 2.0 * v[115];
        let s230 = -2.0 * v[116];
        let s231 = -2.0 * v[117];
        let s232 = 2.0 * v[116];
        let s233 = 2.0 * v[117];
        let s234 = -2.0 * v[118];
        let s235 = -2.0 * v[119];
        let s236 = 2.0 * v[118];
        let s237 = 2.0 * v[119];
        let s238 = -2.0 * v[120];
        let s239 = -2.0 * v[121];
        let s240 = 2.0 * v[120];
        let s241 = 2.0 * v[121];
        let s242 = -2.0 * v[122];
        let s243 = -2.0 * v[123];
        let s244 = 2.0 * v[122];
        let s245 = 2.0 * v[123];
        let s246 = -2.0 * v[124];
        let s247 = -2.0 * v[125];
        let s248 = 2.0 * v[124];
        let s249 = 2.0 * v[125];
        let s250 = -2.0 * v[126];
        let s251 = -2.0 * v[127];
        let s252 = 2.0 * v[126];
        let s253 = 2.0 * v[127];
        let s254 = -2.0 * v[128];
        let s255 = -2.0 * v[129];
        let s256 = 2.0 * v[128];
        let s257 = 2.0 * v[129];
        let s258 = -2.0 * v[130];
        let s259 = -2.0 * v[131];
        let s260 = 2.0 * v[130];
        let s261 = 2.0 * v[131];
        let s262 = -2.0 * v[132];
        let s263 = -2.0 * v[133];
        let s264 = 2.0 * v[132];
        let s265 = 2.0 * v[133];
        let s266 = -2.0 * v[134];
        let s267 = -2.0 * v[135];
        let s268 = 2.0 * v[134];
        let s269 = 2.0 * v[135];
        let s270 = -2.0 * v[136];
        let s271 = -2.0 * v[137];
        let s272 = 2.0 * v[136];
        let s273 = 2.0 * v[137];
        let s274 = -2.0 * v[138];
        let s275 = -2.0 * v[139];
        let s276 = 2.0 * v[138];
        let s277 = 2.0 * v[139];
        let s278 = -2.0 * v[140];
        let s279 = -2.0 * v[141];
        let s280 = 2.0 * v[140];
        let s281 = 2.0 * v[141];
        let s282 = -2.0 * v[142];
        let s283 = -2.0 * v[143];
        let s284 = 2.0 * v[142];
        let s285 = 2.0 * v[143];
        let s286 = -2.0 * v[144];
        let s287 = -2.0 * v[145];
        let s288 = 2.0 * v[144];
        let s289 = 2.0 * v[145];
        let s290 = -2.0 * v[146];
        let s291 = -2.0 * v[147];
        let s292 = 2.0 * v[146];
        let s293 = 2.0 * v[147];
        let s294 = -2.0 * v[148];
        let s295 = -2.0 * v[149];
        let s296 = 2.0 * v[148];
        let s297 = 2.0 * v[149];
        let s298 = -2.0 * v[150];
        let s299 = -2.0 * v[151];
        let s300 = 2.0 * v[150];
        let s301 = 2.0 * v[151];
        let s302 = -2.0 * v[152];
        let s303 = -2.0 * v[153];
        let s304 = 2.0 * v[152];
        let s305 = 2.0 * v[153];
        let s306 = -2.0 * v[154];
        let s307 = -2.0 * v[155];
        let s308 = 2.0 * v[154];
        let s309 = 2.0 * v[155];
        let s310 = -2.0 * v[156];
        let s311 = -2.0 * v[157];
        let s312 = 2.0 * v[156];
        let s313 = 2.0 * v[157];
        let s314 = -2.0 * v[158];
        let s315 = -2.0 * v[159];
        let s316 = 2.0 * v[158];
        let s317 = 2.0 * v[159];
        let s318 = -2.0 * v[160];
        let s319 = -2.0 * v[161];
        let s320 = 2.0 * v[160];
        let s321 = 2.0 * v[161];
        let s322 = -2.0 * v[162];
        let s323 = -2.0 * v[163];
        let s324 = 2.0 * v[162];
        let s325 = 2.0 * v[163];
        let s326 = -2.0 * v[164];
        let s327 = -2.0 * v[165];
        let s328 = 2.0 * v[164];
        let s329 = 2.0 * v[165];
        let s330 = -2.0 * v[166];
        let s331 = -2.0 * v[167];
        let s332 = 2.0 * v[166];
        let s333 = 2.0 * v[167];
        let s334 = -2.0 * v[168];
        let s335 = -2.0 * v[169];
        let s336 = 2.0 * v[168];
        let s337 = 2.0 * v[169];
        let s338 = -2.0 * v[170];
        let s339 = -2.0 * v[171];
        let s340 = 2.0 * v[170];
        let s341 = 2.0 * v[171];
        let s342 = -2.0 * v[172];
        let s343 = -2.0 * v[173];
        let s344 = 2.0 * v[172];
        let s345 = 2.0 * v[173];
        let s346 = -2.0 * v[174];
        let s347 = -2.0 * v[175];
        let s348 = 2.0 * v[174];
        let s349 = 2.0 * v[175];
        let s350 = -2.0 * v[176];
        let s351 = -2.0 * v[177];
        let s352 = 2.0 * v[176];
        let s353 = 2.0 * v[177];
        let s354 = -2.0 * v[178];
        let s355 = -2.0 * v[179];
        let s356 = 2.0 * v[178];
        let s357 = 2.0 * v[179];
        let s358 = -2.0 * v[180];
        let s359 = -2.0 * v[181];
        let s360 = 2.0 * v[180];
        let s361 = 2.0 * v[181];
        let s362 = -2.0 * v[182];
        let s363 = -2.0 * v[183];
        let s364 = 2.0 * v[182];
        let s365 = 2.0 * v[183];
        let s366 = -2.0 * v[184];
        let s367 = -2.0 * v[185];
        let s368 = 2.0 * v[184];
        let s369 = 2.0 * v[185];
        let s370 = -2.0 * v[186];
        let s371 = -2.0 * v[187];
        let s372 = 2.0 * v[186];
        let s373 = 2.0 * v[187];
        let s374 = -2.0 * v[188];
        let s375 = -2.0 * v[189];
        let s376 = 2.0 * v[188];
        let s377 = 2.0 * v[189];
        let s378 = -2.0 * v[190];
        let s379 = -2.0 * v[191];
        let s380 = 2.0 * v[190];
        let s381 = 2.0 * v[191];
        let s382 = -2.0 * v[192];
        let s383 = -2.0 * v[193];
        let s384 = 2.0 * v[192];
        let s385 = 2.0 * v[193];
        let s386 = -2.0 * v[194];
        let s387 = -2.0 * v[195];
        let s388 = 2.0 * v[194];
        let s389 = 2.0 * v[195];
        let s390 = -2.0 * v[196];
        let s391 = -2.0 * v[197];
        let s392 = 2.0 * v[196];
        let s393 = 2.0 * v[197];
        let mut b = ::zeitner::__private::Vector::<100>::zeros();
        b[0] = v[0] * s0 + v[1] * s1;
        b[1] = v[0] * (s2 - -2.0 * v[0]) + v[1] * (s3 - -2.0 * v[1]) + v[2] * (s4 - s0)
            + v[3] * (s5 - s1);
        b[2] = v[2] * (s6 - s2) + v[3] * (s7 - s3) + v[4] * (s8 - s4) + v[5] * (s9 - s5);
        b[3] = v[4] * (s10 - s6) + v[5] * (s11 - s7) + v[6] * (s12 - s8)
            + v[7] * (s13 - s9);
        b[4] = v[6] * (s14 - s10) + v[7] * (s15 - s11) + v[8] * (s16 - s12)
            + v[9] * (s17 - s13);
        b[5] = v[8] * (s18 - s14) + v[9] * (s19 - s15) + v[10] * (s20 - s16)
            + v[11] * (s21 - s17);
        b[6] = v[10] * (s22 - s18) + v[11] * (s23 - s19) + v[12] * (s24 - s20)
            + v[13] * (s25 - s21);
        b[7] = v[12] * (s26 - s22) + v[13] * (s27 - s23) + v[14] * (s28 - s24)
            + v[15] * (s29 - s25);
        b[8] = v[14] * (s30 - s26) + v[15] * (s31 - s27) + v[16] * (s32 - s28)
            + v[17] * (s33 - s29);
        b[9] = v[16] * (s34 - s30) + v[17] * (s35 - s31) + v[18] * (s36 - s32)
            + v[19] * (s37 - s33);
        b[10] = v[18] * (s38 - s34) + v[19] * (s39 - s35) + v[20] * (s40 - s36)
            + v[21] * (s41 - s37);
        b[11] = v[20] * (s42 - s38) + v[21] * (s43 - s39) + v[22] * (s44 - s40)
            + v[23] * (s45 - s41);
        b[12] = v[22] * (s46 - s42) + v[23] * (s47 - s43) + v[24] * (s48 - s44)
            + v[25] * (s49 - s45);
        b[13] = v[24] * (s50 - s46) + v[25] * (s51 - s47) + v[26] * (s52 - s48)
            + v[27] * (s53 - s49);
        b[14] = v[26] * (s54 - s50) + v[27] * (s55 - s51) + v[28] * (s56 - s52)
            + v[29] * (s57 - s53);
        b[15] = v[28] * (s58 - s54) + v[29] * (s59 - s55) + v[30] * (s60 - s56)
            + v[31] * (s61 - s57);
        b[16] = v[30] * (s62 - s58) + v[31] * (s63 - s59) + v[32] * (s64 - s60)
            + v[33] * (s65 - s61);
        b[17] = v[32] * (s66 - s62) + v[33] * (s67 - s63) + v[34] * (s68 - s64)
            + v[35] * (s69 - s65);
        b[18] = v[34] * (s70 - s66) + v[35] * (s71 - s67) + v[36] * (s72 - s68)
            + v[37] * (s73 - s69);
        b[19] = v[36] * (s74 - s70) + v[37] * (s75 - s71) + v[38] * (s76 - s72)
            + v[39] * (s77 - s73);
        b[20] = v[38] * (s78 - s74) + v[39] * (s79 - s75) + v[40] * (s80 - s76)
            + v[41] * (s81 - s77);
        b[21] = v[40] * (s82 - s78) + v[41] * (s83 - s79) + v[42] * (s84 - s80)
            + v[43] * (s85 - s81);
        b[22] = v[42] * (s86 - s82) + v[43] * (s87 - s83) + v[44] * (s88 - s84)
            + v[45] * (s89 - s85);
        b[23] = v[44] * (s90 - s86) + v[45] * (s91 - s87) + v[46] * (s92 - s88)
            + v[47] * (s93 - s89);
        b[24] = v[46] * (s94 - s90) + v[47] * (s95 - s91) + v[48] * (s96 - s92)
            + v[49] * (s97 - s93);
        b[25] = v[48] * (s98 - s94) + v[49] * (s99 - s95) + v[50] * (s100 - s96)
            + v[51] * (s101 - s97);
        b[26] = v[50] * (s102 - s98) + v[51] * (s103 - s99) + v[52] * (s104 - s100)
            + v[53] * (s105 - s101);
        b[27] = v[52] * (s106 - s102) + v[53] * (s107 - s103) + v[54] * (s108 - s104)
            + v[55] * (s109 - s105);
        b[28] = v[54] * (s110 - s106) + v[55] * (s111 - s107) + v[56] * (s112 - s108)
            + v[57] * (s113 - s109);
        b[29] = v[56] * (s114 - s110) + v[57] * (s115 - s111) + v[58] * (s116 - s112)
            + v[59] * (s117 - s113);
        b[30] = v[58] * (s118 - s114) + v[59] * (s119 - s115) + v[60] * (s120 - s116)
            + v[61] * (s121 - s117);
        b[31] = v[60] * (s122 - s118) + v[61] * (s123 - s119) + v[62] * (s124 - s120)
            + v[63] * (s125 - s121);
        b[32] = v[62] * (s126 - s122) + v[63] * (s127 - s123) + v[64] * (s128 - s124)
            + v[65] * (s129 - s125);
        b[33] = v[64] * (s130 - s126) + v[65] * (s131 - s127) + v[66] * (s132 - s128)
            + v[67] * (s133 - s129);
        b[34] = v[66] * (s134 - s130) + v[67] * (s135 - s131) + v[68] * (s136 - s132)
            + v[69] * (s137 - s133);
        b[35] = v[68] * (s138 - s134) + v[69] * (s139 - s135) + v[70] * (s140 - s136)
            + v[71] * (s141 - s137);
        b[36] = v[70] * (s142 - s138) + v[71] * (s143 - s139) + v[72] * (s144 - s140)
            + v[73] * (s145 - s141);
        b[37] = v[72] * (s146 - s142) + v[73] * (s147 - s143) + v[74] * (s148 - s144)
            + v[75] * (s149 - s145);
        b[38] = v[74] * (s150 - s146) + v[75] * (s151 - s147) + v[76] * (s152 - s148)
            + v[77] * (s153 - s149);
        b[39] = v[76] * (s154 - s150) + v[77] * (s155 - s151) + v[78] * (s156 - s152)
            + v[79] * (s157 - s153);
        b[40] = v[78] * (s158 - s154) + v[79] * (s159 - s155) + v[80] * (s160 - s156)
            + v[81] * (s161 - s157);
        b[41] = v[80] * (s162 - s158) + v[81] * (s163 - s159) + v[82] * (s164 - s160)
            + v[83] * (s165 - s161);
        b[42] = v[82] * (s166 - s162) + v[83] * (s167 - s163) + v[84] * (s168 - s164)
            + v[85] * (s169 - s165);
        b[43] = v[84] * (s170 - s166) + v[85] * (s171 - s167) + v[86] * (s172 - s168)
            + v[87] * (s173 - s169);
        b[44] = v[86] * (s174 - s170) + v[87] * (s175 - s171) + v[88] * (s176 - s172)
            + v[89] * (s177 - s173);
        b[45] = v[88] * (s178 - s174) + v[89] * (s179 - s175) + v[90] * (s180 - s176)
            + v[91] * (s181 - s177);
        b[46] = v[90] * (s182 - s178) + v[91] * (s183 - s179) + v[92] * (s184 - s180)
            + v[93] * (s185 - s181);
        b[47] = v[92] * (s186 - s182) + v[93] * (s187 - s183) + v[94] * (s188 - s184)
            + v[95] * (s189 - s185);
        b[48] = v[94] * (s190 - s186) + v[95] * (s191 - s187) + v[96] * (s192 - s188)
            + v[97] * (s193 - s189);
        b[49] = v[96] * (s194 - s190) + v[97] * (s195 - s191) + v[98] * (s196 - s192)
            + v[99] * (s197 - s193);
        b[50] = v[98] * (s198 - s194) + v[99] * (s199 - s195) + v[100] * (s200 - s196)
            + v[101] * (s201 - s197);
        b[51] = v[100] * (s202 - s198) + v[101] * (s203 - s199) + v[102] * (s204 - s200)
            + v[103] * (s205 - s201);
        b[52] = v[102] * (s206 - s202) + v[103] * (s207 - s203) + v[104] * (s208 - s204)
            + v[105] * (s209 - s205);
        b[53] = v[104] * (s210 - s206) + v[105] * (s211 - s207) + v[106] * (s212 - s208)
            + v[107] * (s213 - s209);
        b[54] = v[106] * (s214 - s210) + v[107] * (s215 - s211) + v[108] * (s216 - s212)
            + v[109] * (s217 - s213);
        b[55] = v[108] * (s218 - s214) + v[109] * (s219 - s215) + v[110] * (s220 - s216)
            + v[111] * (s221 - s217);
        b[56] = v[110] * (s222 - s218) + v[111] * (s223 - s219) + v[112] * (s224 - s220)
            + v[113] * (s225 - s221);
        b[57] = v[112] * (s226 - s222) + v[113] * (s227 - s223) + v[114] * (s228 - s224)
            + v[115] * (s229 - s225);
        b[58] = v[114] * (s230 - s226) + v[115] * (s231 - s227) + v[116] * (s232 - s228)
            + v[117] * (s233 - s229);
        b[59] = v[116] * (s234 - s230) + v[117] * (s235 - s231) + v[118] * (s236 - s232)
            + v[119] * (s237 - s233);
        b[60] = v[118] * (s238 - s234) + v[119] * (s239 - s235) + v[120] * (s240 - s236)
            + v[121] * (s241 - s237);
        b[61] = v[120] * (s242 - s238) + v[121] * (s243 - s239) + v[122] * (s244 - s240)
            + v[123] * (s245 - s241);
        b[62] = v[122] * (s246 - s242) + v[123] * (s247 - s243) + v[124] * (s248 - s244)
            + v[125] * (s249 - s245);
        b[63] = v[124] * (s250 - s246) + v[125] * (s251 - s247) + v[126] * (s252 - s248)
            + v[127] * (s253 - s249);
        b[64] = v[126] * (s254 - s250) + v[127] * (s255 - s251) + v[128] * (s256 - s252)
            + v[129] * (s257 - s253);
        b[65] = v[128] * (s258 - s254) + v[129] * (s259 - s255) + v[130] * (s260 - s256)
            + v[131] * (s261 - s257);
        b[66] = v[130] * (s262 - s258) + v[131] * (s263 - s259) + v[132] * (s264 - s260)
            + v[133] * (s265 - s261);
        b[67] = v[132] * (s266 - s262) + v[133] * (s267 - s263) + v[134] * (s268 - s264)
            + v[135] * (s269 - s265);
        b[68] = v[134] * (s270 - s266) + v[135] * (s271 - s267) + v[136] * (s272 - s268)
            + v[137] * (s273 - s269);
        b[69] = v[136] * (s274 - s270) + v[137] * (s275 - s271) + v[138] * (s276 - s272)
            + v[139] * (s277 - s273);
        b[70] = v[138] * (s278 - s274) + v[139] * (s279 - s275) + v[140] * (s280 - s276)
            + v[141] * (s281 - s277);
        b[71] = v[140] * (s282 - s278) + v[141] * (s283 - s279) + v[142] * (s284 - s280)
            + v[143] * (s285 - s281);
        b[72] = v[142] * (s286 - s282) + v[143] * (s287 - s283) + v[144] * (s288 - s284)
            + v[145] * (s289 - s285);
        b[73] = v[144] * (s290 - s286) + v[145] * (s291 - s287) + v[146] * (s292 - s288)
            + v[147] * (s293 - s289);
        b[74] = v[146] * (s294 - s290) + v[147] * (s295 - s291) + v[148] * (s296 - s292)
            + v[149] * (s297 - s293);
        b[75] = v[148] * (s298 - s294) + v[149] * (s299 - s295) + v[150] * (s300 - s296)
            + v[151] * (s301 - s297);
        b[76] = v[150] * (s302 - s298) + v[151] * (s303 - s299) + v[152] * (s304 - s300)
            + v[153] * (s305 - s301);
        b[77] = v[152] * (s306 - s302) + v[153] * (s307 - s303) + v[154] * (s308 - s304)
            + v[155] * (s309 - s305);
        b[78] = v[154] * (s310 - s306) + v[155] * (s311 - s307) + v[156] * (s312 - s308)
            + v[157] * (s313 - s309);
        b[79] = v[156] * (s314 - s310) + v[157] * (s315 - s311) + v[158] * (s316 - s312)
            + v[159] * (s317 - s313);
        b[80] = v[158] * (s318 - s314) + v[159] * (s319 - s315) + v[160] * (s320 - s316)
            + v[161] * (s321 - s317);
        b[81] = v[160] * (s322 - s318) + v[161] * (s323 - s319) + v[162] * (s324 - s320)
            + v[163] * (s325 - s321);
        b[82] = v[162] * (s326 - s322) + v[163] * (s327 - s323) + v[164] * (s328 - s324)
            + v[165] * (s329 - s325);
        b[83] = v[164] * (s330 - s326) + v[165] * (s331 - s327) + v[166] * (s332 - s328)
            + v[167] * (s333 - s329);
        b[84] = v[166] * (s334 - s330) + v[167] * (s335 - s331) + v[168] * (s336 - s332)
            + v[169] * (s337 - s333);
        b[85] = v[168] * (s338 - s334) + v[169] * (s339 - s335) + v[170] * (s340 - s336)
            + v[171] * (s341 - s337);
        b[86] = v[170] * (s342 - s338) + v[171] * (s343 - s339) + v[172] * (s344 - s340)
            + v[173] * (s345 - s341);
        b[87] = v[172] * (s346 - s342) + v[173] * (s347 - s343) + v[174] * (s348 - s344)
            + v[175] * (s349 - s345);
        b[88] = v[174] * (s350 - s346) + v[175] * (s351 - s347) + v[176] * (s352 - s348)
            + v[177] * (s353 - s349);
        b[89] = v[176] * (s354 - s350) + v[177] * (s355 - s351) + v[178] * (s356 - s352)
            + v[179] * (s357 - s353);
        b[90] = v[178] * (s358 - s354) + v[179] * (s359 - s355) + v[180] * (s360 - s356)
            + v[181] * (s361 - s357);
        b[91] = v[180] * (s362 - s358) + v[181] * (s363 - s359) + v[182] * (s364 - s360)
            + v[183] * (s365 - s361);
        b[92] = v[182] * (s366 - s362) + v[183] * (s367 - s363) + v[184] * (s368 - s364)
            + v[185] * (s369 - s365);
        b[93] = v[184] * (s370 - s366) + v[185] * (s371 - s367) + v[186] * (s372 - s368)
            + v[187] * (s373 - s369);
        b[94] = v[186] * (s374 - s370) + v[187] * (s375 - s371) + v[188] * (s376 - s372)
            + v[189] * (s377 - s373);
        b[95] = v[188] * (s378 - s374) + v[189] * (s379 - s375) + v[190] * (s380 - s376)
            + v[191] * (s381 - s377);
        b[96] = v[190] * (s382 - s378) + v[191] * (s383 - s379) + v[192] * (s384 - s380)
            + v[193] * (s385 - s381);
        b[97] = v[192] * (s386 - s382) + v[193] * (s387 - s383) + v[194] * (s388 - s384)
            + v[195] * (s389 - s385);
        b[98] = v[194] * (s390 - s386) + v[195] * (s391 - s387) + v[196] * (s392 - s388)
            + v[197] * (s393 - s389);
        b[99] = v[196] * (-2.0 * v[198] - s390) + v[197] * (-2.0 * v[199] - s391)
            + v[198] * (2.0 * v[198] - s392) + v[199] * (2.0 * v[199] - s393);
        b
    }
    #[inline]
    fn force_jacobians(
        &self,
        q: &::zeitner::__private::Vector<200>,
        v: &::zeitner::__private::Vector<200>,
        t: ::zeitner::__private::Float,
    ) -> (
        ::zeitner::__private::Matrix<200, 200>,
        ::zeitner::__private::Matrix<200, 200>,
    ) {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let mut dq = ::zeitner::__private::Matrix::<200, 200>::zeros();
        let mut dv = ::zeitner::__private::Matrix::<200, 200>::zeros();
        (dq, dv)
    }
    #[inline]
    fn constraint_force_jacobians(
        &self,
        q: &::zeitner::__private::Vector<200>,
        v: &::zeitner::__private::Vector<200>,
        t: ::zeitner::__private::Float,
        lambda: &::zeitner::__private::Vector<100>,
    ) -> (
        ::zeitner::__private::Matrix<200, 200>,
        ::zeitner::__private::Matrix<200, 200>,
    ) {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let s0 = -2.0 * lambda[1];
        let s1 = 2.0 * lambda[0] - s0;
        let s2 = 2.0 * lambda[1];
        let s3 = -s2;
        let s4 = -2.0 * lambda[2];
        let s5 = s2 - s4;
        let s6 = 2.0 * lambda[2];
        let s7 = -s6;
        let s8 = -2.0 * lambda[3];
        let s9 = s6 - s8;
        let s10 = 2.0 * lambda[3];
        let s11 = -s10;
        let s12 = -2.0 * lambda[4];
        let s13 = s10 - s12;
        let s14 = 2.0 * lambda[4];
        let s15 = -s14;
        let s16 = -2.0 * lambda[5];
        let s17 = s14 - s16;
        let s18 = 2.0 * lambda[5];
        let s19 = -s18;
        let s20 = -2.0 * lambda[6];
        let s21 = s18 - s20;
        let s22 = 2.0 * lambda[6];
        let s23 = -s22;
        let s24 = -2.0 * lambda[7];
        let s25 = s22 - s24;
        let s26 = 2.0 * lambda[7];
        let s27 = -s26;
        let s28 = -2.0 * lambda[8];
        let s29 = s26 - s28;
        let s30 = 2.0 * lambda[8];
        let s31 = -s30;
        let s32 = -2.0 * lambda[9];
        let s33 = s30 - s32;
        let s34 = 2.0 * lambda[9];
        let s35 = -s34;
        let s36 = -2.0 * lambda[10];
        let s37 = s34 - s36;
        let s38 = 2.0 * lambda[10];
        let s39 = -s38;
        let s40 = -2.0 * lambda[11];
        let s41 = s38 - s40;
        let s42 = 2.0 * lambda[11];
        let s43 = -s42;
        let s44 = -2.0 * lambda[12];
        let s45 = s42 - s44;
        let s46 = 2.0 * lambda[12];
        let s47 = -s46;
        let s48 = -2.0 * lambda[13];
        let s49 = s46 - s48;
        let s50 = 2.0 * lambda[13];
        let s51 = -s50;
        let s52 = -2.0 * lambda[14];
        let s53 = s50 - s52;
        let s54 = 2.0 * lambda[14];
        let s55 = -s54;
        let s56 = -2.0 * lambda[15];
        let s57 = s54 - s56;
        let s58 = 2.0 * lambda[15];
        let s59 = -s58;
        let s60 = -2.0 * lambda[16];
        let s61 = s58 - s60;
        let s62 = 2.0 * lambda[16];
        let s63 = -s62;
        let s64 = -2.0 * lambda[17];
        let s65 = s62 - s64;
        let s66 = 2.0 * lambda[17];
        let s67 = -s66;
        let s68 = -2.0 * lambda[18];
        let s69 = s66 - s68;
        let s70 = 2.0 * lambda[18];
        let s71 = -s70;
        let s72 = -2.0 * lambda[19];
        let s73 = s70 - s72;
        let s74 = 2.0 * lambda[19];
        let s75 = -s74;
        let s76 = -2.0 * lambda[20];
        let s77 = s74 - s76;
        let s78 = 2.0 * lambda[20];
        let s79 = -s78;
        let s80 = -2.0 * lambda[21];
        let s81 = s78 - s80;
        let s82 = 2.0 * lambda[21];
        let s83 = -s82;
        let s84 = -2.0 * lambda[22];
        let s85 = s82 - s84;
        let s86 = 2.0 * lambda[22];
        let s87 = -s86;
        let s88 = -2.0 * lambda[23];
        let s89 = s86 - s88;
        let s90 = 2.0 * lambda[23];
        let s91 = -s90;
        let s92 = -2.0 * lambda[24];
        let s93 = s90 - s92;
        let s94 = 2.0 * lambda[24];
        let s95 = -s94;
        let s96 = -2.0 * lambda[25];
        let s97 = s94 - s96;
        let s98 = 2.0 * lambda[25];
        let s99 = -s98;
        let s100 = -2.0 * lambda[26];
        let s101 = s98 - s100;
        let s102 = 2.0 * lambda[26];
        let s103 = -s102;
        let s104 = -2.0 * lambda[27];
        let s105 = s102 - s104;
        let s106 = 2.0 * lambda[27];
        let s107 = -s106;
        let s108 = -2.0 * lambda[28];
        let s109 = s106 - s108;
        let s110 = 2.0 * lambda[28];
        let s111 = -s110;
        let s112 = -2.0 * lambda[29];
        let s113 = s110 - s112;
        let s114 = 2.0 * lambda[29];
        let s115 = -s114;
        let s116 = -2.0 * lambda[30];
        let s117 = s114 - s116;
        let s118 = 2.0 * lambda[30];
        let s119 = -s118;
        let s120 = -2.0 * lambda[31];
        let s121 = s118 - s120;
        let s122 = 2.0 * lambda[31];
        let s123 = -s122;
        let s124 = -2.0 * lambda[32];
        let s125 = s122 - s124;
        let s126 = 2.0 * lambda[32];
        let s127 = -s126;
        let s128 = -2.0 * lambda[33];
        let s129 = s126 - s128;
        let s130 = 2.0 * lambda[33];
        let s131 = -s130;
        let s132 = -2.0 * lambda[34];
        let s133 = s130 - s132;
        let s134 = 2.0 * lambda[34];
        let s135 = -s134;
        let s136 = -2.0 * lambda[35];
        let s137 = s134 - s136;
        let s138 = 2.0 * lambda[35];
        let s139 = -s138;
        let s140 = -2.0 * lambda[36];
        let s141 = s138 - s140;
        let s142 = 2.0 * lambda[36];
        let s143 = -s142;
        let s144 = -2.0 * lambda[37];
        let s145 = s142 - s144;
        let s146 = 2.0 * lambda[37];
        let s147 = -s146;
        let s148 = -2.0 * lambda[38];
        let s149 = s146 - s148;
        let s150 = 2.0 * lambda[38];
        let s151 = -s150;
        let s152 = -2.0 * lambda[39];
        let s153 = s150 - s152;
        let s154 = 2.0 * lambda[39];
        let s155 = -s154;
        let s156 = -2.0 * lambda[40];
        let s157 = s154 - s156;
        let s158 = 2.0 * lambda[40];
        let s159 = -s158;
        let s160 = -2.0 * lambda[41];
        let s161 = s158 - s160;
        let s162 = 2.0 * lambda[41];
        let s163 = -s162;
        let s164 = -2.0 * lambda[42];
        let s165 = s162 - s164;
        let s166 = 2.0 * lambda[42];
        let s167 = -s166;
        let s168 = -2.0 * lambda[43];
        let s169 = s166 - s168;
        let s170 = 2.0 * lambda[43];
        let s171 = -s170;
        let s172 = -2.0 * lambda[44];
        let s173 = s170 - s172;
        let s174 = 2.0 * lambda[44];
        let s175 = -s174;
        let s176 = -2.0 * lambda[45];
        let s177 = s174 - s176;
        let s178 = 2.0 * lambda[45];
        let s179 = -s178;
        let s180 = -2.0 * lambda[46];
        let s181 = s178 - s180;
        let s182 = 2.0 * lambda[46];
        let s183 = -s182;
        let s184 = -2.0 * lambda[47];
        let s185 = s182 - s184;
        let s186 = 2.0 * lambda[47];
        let s187 = -s186;
        let s188 = -2.0 * lambda[48];
        let s189 = s186 - s188;
        let s190 = 2.0 * lambda[48];
        let s191 = -s190;
        let s192 = -2.0 * lambda[49];
        let s193 = s190 - s192;
        let s194 = 2.0 * lambda[49];
        let s195 = -s194;
        let s196 = -2.0 * lambda[50];
        let s197 = s194 - s196;
        let s198 = 2.0 * lambda[50];
        let s199 = -s198;
        let s200 = -2.0 * lambda[51];
        let s201 = s198 - s200;
        let s202 = 2.0 * lambda[51];
        let s203 = -s202;
        let s204 = -2.0 * lambda[52];
        let s205 = s202 - s204;
        let s206 = 2.0 * lambda[52];
        let s207 = -s206;
        let s208 = -2.0 * lambda[53];
        let s209 = s206 - s208;
        let s210 = 2.0 * lambda[53];
        let s211 = -s210;
        let s212 = -2.0 * lambda[54];
        let s213 = s210 - s212;
        let s214 = 2.0 * lambda[54];
        let s215 = -s214;
        let s216 = -2.0 * lambda[55];
        let s217 = s214 - s216;
        let s218 = 2.0 * lambda[55];
        let s219 = -s218;
        let s220 = -2.0 * lambda[56];
        let s221 = s218 - s220;
        let s222 = 2.0 * lambda[56];
        let s223 = -s222;
        let s224 = -2.0 * lambda[57];
        let s225 = s222 - s224;
        let s226 = 2.0 * lambda[57];
        let s227 = -s226;
        let s228 = -2.0 * lambda[58];
        let s229 = s226 - s228;
        let s230 = 2.0 * lambda[58];
        let s231 = -s230;
        let s232 = -2.0 * lambda[59];
        let s233 = s230 - s232;
        let s234 = 2.0 * lambda[59];
        let s235 = -s234;
        let s236 = -2.0 * lambda[60];
        let s237 = s234 - s236;
        let s238 = 2.0 * lambda[60];
        let s239 = -s238;
        let s240 = -2.0 * lambda[61];
        let s241 = s238 - s240;
        let s242 = 2.0 * lambda[61];
        let s243 = -s242;
        let s244 = -2.0 * lambda[62];
        let s245 = s242 - s244;
        let s246 = 2.0 * lambda[62];
        let s247 = -s246;
        let s248 = -2.0 * lambda[63];
        let s249 = s246 - s248;
        let s250 = 2.0 * lambda[63];
        let s251 = -s250;
        let s252 = -2.0 * lambda[64];
        let s253 = s250 - s252;
        let s254 = 2.0 * lambda[64];
        let s255 = -s254;
        let s256 = -2.0 * lambda[65];
        let s257 = s254 - s256;
        let s258 = 2.0 * lambda[65];
        let s259 = -s258;
        let s260 = -2.0 * lambda[66];
        let s261 = s258 - s260;
        let s262 = 2.0 * lambda[66];
        let s263 = -s262;
        let s264 = -2.0 * lambda[67];
        let s265 = s262 - s264;
        let s266 = 2.0 * lambda[67];
        let s267 = -s266;
        let s268 = -2.0 * lambda[68];
        let s269 = s266 - s268;
        let s270 = 2.0 * lambda[68];
        let s271 = -s270;
        let s272 = -2.0 * lambda[69];
        let s273 = s270 - s272;
        let s274 = 2.0 * lambda[69];
        let s275 = -s274;
        let s276 = -2.0 * lambda[70];
        let s277 = s274 - s276;
        let s278 = 2.0 * lambda[70];
        let s279 = -s278;
        let s280 = -2.0 * lambda[71];
        let s281 = s278 - s280;
        let s282 = 2.0 * lambda[71];
        let s283 = -s282;
        let s284 = -2.0 * lambda[72];
        let s285 = s282 - s284;
        let s286 = 2.0 * lambda[72];
        let s287 = -s286;
        let s288 = -2.0 * lambda[73];
        let s289 = s286 - s288;
        let s290 = 2.0 * lambda[73];
        let s291 = -s290;
        let s292 = -2.0 * lambda[74];
        let s293 = s290 - s292;
        let s294 = 2.0 * lambda[74];
        let s295 = -s294;
        let s296 = -2.0 * lambda[75];
        let s297 = s294 - s296;
        let s298 = 2.0 * lambda[75];
        let s299 = -s298;
        let s300 = -2.0 * lambda[76];
        let s301 = s298 - s300;
        let s302 = 2.0 * lambda[76];
        let s303 = -s302;
        let s304 = -2.0 * lambda[77];
        let s305 = s302 - s304;
        let s306 = 2.0 * lambda[77];
        let s307 = -s306;
        let s308 = -2.0 * lambda[78];
        let s309 = s306 - s308;
        let s310 = 2.0 * lambda[78];
        let s311 = -s310;
        let s312 = -2.0 * lambda[79];
        let s313 = s310 - s312;
        let s314 = 2.0 * lambda[79];
        let s315 = -s314;
        let s316 = -2.0 * lambda[80];
        let s317 = s314 - s316;
        let s318 = 2.0 * lambda[80];
        let s319 = -s318;
        let s320 = -2.0 * lambda[81];
        let s321 = s318 - s320;
        let s322 = 2.0 * lambda[81];
        let s323 = -s322;
        let s324 = -2.0 * lambda[82];
        let s325 = s322 - s324;
        let s326 = 2.0 * lambda[82];
        let s327 = -s326;
        let s328 = -2.0 * lambda[83];
        let s329 = s326 - s328;
        let s330 = 2.0 * lambda[83];
        let s331 = -s330;
        let s332 = -2.0 * lambda[84];
        let s333 = s330 - s332;
        let s334 = 2.0 * lambda[84];
        let s335 = -s334;
        let s336 = -2.0 * lambda[85];
        let s337 = s334 - s336;
        let s338 = 2.0 * lambda[85];
        let s339 = -s338;
        let s340 = -2.0 * lambda[86];
        let s341 = s338 - s340;
        let s342 = 2.0 * lambda[86];
        let s343 = -s342;
        let s344 = -2.0 * lambda[87];
        let s345 = s342 - s344;
        let s346 = 2.0 * lambda[87];
        let s347 = -s346;
        let s348 = -2.0 * lambda[88];
        let s349 = s346 - s348;
        let s350 = 2.0 * lambda[88];
        let s351 = -s350;
        let s352 = -2.0 * lambda[89];
        let s353 = s350 - s352;
        let s354 = 2.0 * lambda[89];
        let s355 = -s354;
        let s356 = -2.0 * lambda[90];
        let s357 = s354 - s356;
        let s358 = 2.0 * lambda[90];
        let s359 = -s358;
        let s360 = -2.0 * lambda[91];
        let s361 = s358 - s360;
        let s362 = 2.0 * lambda[91];
        let s363 = -s362;
        let s364 = -2.0 * lambda[92];
        let s365 = s362 - s364;
        let s366 = 2.0 * lambda[92];
        let s367 = -s366;
        let s368 = -2.0 * lambda[93];
        let s369 = s366 - s368;
        let s370 = 2.0 * lambda[93];
        let s371 = -s370;
        let s372 = -2.0 * lambda[94];
        let s373 = s370 - s372;
        let s374 = 2.0 * lambda[94];
        let s375 = -s374;
        let s376 = -2.0 * lambda[95];
        let s377 = s374 - s376;
        let s378 = 2.0 * lambda[95];
        let s379 = -s378;
        let s380 = -2.0 * lambda[96];
        let s381 = s378 - s380;
        let s382 = 2.0 * lambda[96];
        let s383 = -s382;
        let s384 = -2.0 * lambda[97];
        let s385 = s382 - s384;
        let s386 = 2.0 * lambda[97];
        let s387 = -s386;
        let s388 = -2.0 * lambda[98];
        let s389 = s386 - s388;
        let s390 = 2.0 * lambda[98];
        let s391 = -s390;
        let s392 = -2.0 * lambda[99];
        let s393 = s390 - s392;
        let s394 = 2.0 * lambda[99];
        let s395 = -s394;
        let mut dq = ::zeitner::__private::Matrix::<200, 200>::zeros();
        let mut dv = ::zeitner::__private::Matrix::<200, 200>::zeros();
        dq[(0, 0)] = s1;
        dq[(0, 2)] = s3;
        dq[(1, 1)] = s1;
        dq[(1, 3)] = s3;
        dq[(2, 0)] = s0;
        dq[(2, 2)] = s5;
        dq[(2, 4)] = s7;
        dq[(3, 1)] = s0;
        dq[(3, 3)] = s5;
        dq[(3, 5)] = s7;
        dq[(4, 2)] = s4;
        dq[(4, 4)] = s9;
        dq[(4, 6)] = s11;
        dq[(5, 3)] = s4;
        dq[(5, 5)] = s9;
        dq[(5, 7)] = s11;
        dq[(6, 4)] = s8;
        dq[(6, 6)] = s13;
        dq[(6, 8)] = s15;
        dq[(7, 5)] = s8;
        dq[(7, 7)] = s13;
        dq[(7, 9)] = s15;
        dq[(8, 6)] = s12;
        dq[(8, 8)] = s17;
        dq[(8, 10)] = s19;
        dq[(9, 7)] = s12;
        dq[(9, 9)] = s17;
        dq[(9, 11)] = s19;
        dq[(10, 8)] = s16;
        dq[(10, 10)] = s21;
        dq[(10, 12)] = s23;
        dq[(11, 9)] = s16;
        dq[(11, 11)] = s21;
        dq[(11, 13)] = s23;
        dq[(12, 10)] = s20;
        dq[(12, 12)] = s25;
        dq[(12, 14)] = s27;
        dq[(13, 11)] = s20;
        dq[(13, 13)] = s25;
        dq[(13, 15)] = s27;
        dq[(14, 12)] = s24;
        dq[(14, 14)] = s29;
        dq[(14, 16)] = s31;
        dq[(15, 13)] = s24;
        dq[(15, 15)] = s29;
        dq[(15, 17)] = s31;
        dq[(16, 14)] = s28;
        dq[(16, 16)] = s33;
        dq[(16, 18)] = s35;
        dq[(17, 15)] = s28;
        dq[(17, 17)] = s33;
        dq[(17, 19)] = s35;
        dq[(18, 16)] = s32;
        dq[(18, 18)] = s37;
        dq[(18, 20)] = s39;
        dq[(19, 17)] = s32;
        dq[(19, 19)] = s37;
        dq[(19, 21)] = s39;
        dq[(20, 18)] = s36;
        dq[(20, 20)] = s41;
        dq[(20, 22)] = s43;
        dq[(21, 19)] = s36;
        dq[(21, 21)] = s41;
        dq[(21, 23)] = s43;
        dq[(22, 20)] = s40;
        dq[(22, 22)] = s45;
        dq[(22, 24)] = s47;
        dq[(23, 21)] = s40;
        dq[(23, 23)] = s45;
        dq[(23, 25)] = s47;
        dq[(24, 22)] = s44;
        dq[(24, 24)] = s49;
        dq[(24, 26)] = s51;
        dq[(25, 23)] = s44;
        dq[(25, 25)] = s49;
        dq[(25, 27)] = s51;
        dq[(26, 24)] = s48;
        dq[(26, 26)] = s53;
        dq[(26, 28)] = s55;
        dq[(27, 25)] = s48;
        dq[(27, 27)] = s53;
        dq[(27, 29)] = s55;
        dq[(28, 26)] = s52;
        dq[(28, 28)] = s57;
        dq[(28, 30)] = s59;
        dq[(29, 27)] = s52;
        dq[(29, 29)] = s57;
        dq[(29, 31)] = s59;
        dq[(30, 28)] = s56;
        dq[(30, 30)] = s61;
        dq[(30, 32)] = s63;
        dq[(31, 29)] = s56;
        dq[(31, 31)] = s61;
        dq[(31, 33)] = s63;
        dq[(32, 30)] = s60;
        dq[(32, 32)] = s65;
        dq[(32, 34)] = s67;
        dq[(33, 31)] = s60;
        dq[(33, 33)] = s65;
        dq[(33, 35)] = s67;
        dq[(34, 32)] = s64;
        dq[(34, 34)] = s69;
        dq[(34, 36)] = s71;
        dq[(35, 33)] = s64;
        dq[(35, 35)] = s69;
        dq[(35, 37)] = s71;
        dq[(36, 34)] = s68;
        dq[(36, 36)] = s73;
        dq[(36, 38)] = s75;
        dq[(37, 35)] = s68;
        dq[(37, 37)] = s73;
        dq[(37, 39)] = s75;
        dq[(38, 36)] = s72;
        dq[(38, 38)] = s77;
        dq[(38, 40)] = s79;
        dq[(39, 37)] = s72;
        dq[(39, 39)] = s77;
        dq[(39, 41)] = s79;
        dq[(40, 38)] = s76;
        dq[(40, 40)] = s81;
        dq[(40, 42)] = s83;
        dq[(41, 39)] = s76;
        dq[(41, 41)] = s81;
        dq[(41, 43)] = s83;
        dq[(42, 40)] = s80;
        dq[(42, 42)] = s85;
        dq[(42, 44)] = s87;
        dq[(43, 41)] = s80;
        dq[(43, 43)] = s85;
        dq[(43, 45)] = s87;
        dq[(44, 42)] = s84;
        dq[(44, 44)] = s89;
        dq[(44, 46)] = s91;
        dq[(45, 43)] = s84;
        dq[(45, 45)] = s89;
        dq[(45, 47)] = s91;
        dq[(46, 44)] = s88;
        dq[(46, 46)] = s93;
        dq[(46, 48)] = s95;
        dq[(47, 45)] = s88;
        dq[(47, 47)] = s93;
        dq[(47, 49)] = s95;
        dq[(48, 46)] = s92;
        dq[(48, 48)] = s97;
        dq[(48, 50)] = s99;
        dq[(49, 47)] = s92;
        dq[(49, 49)] = s97;
        dq[(49, 51)] = s99;
        dq[(50, 48)] = s96;
        dq[(50, 50)] = s101;
        dq[(50, 52)] = s103;
        dq[(51, 49)] = s96;
        dq[(51, 51)] = s101;
        dq[(51, 53)] = s103;
        dq[(52, 50)] = s100;
        dq[(52, 52)] = s105;
        dq[(52, 54)] = s107;
        dq[(53, 51)] = s100;
        dq[(53, 53)] = s105;
        dq[(53, 55)] = s107;
        dq[(54, 52)] = s104;
        dq[(54, 54)] = s109;
        dq[(54, 56)] = s111;
        dq[(55, 53)] = s104;
        dq[(55, 55)] = s109;
        dq[(55, 57)] = s111;
        dq[(56, 54)] = s108;
        dq[(56, 56)] = s113;
        dq[(56, 58)] = s115;
        dq[(57, 55)] = s108;
        dq[(57, 57)] = s113;
        dq[(57, 59)] = s115;
        dq[(58, 56)] = s112;
        dq[(58, 58)] = s117;
        dq[(58, 60)] = s119;
        dq[(59, 57)] = s112;
        dq[(59, 59)] = s117;
        dq[(59, 61)] = s119;
        dq[(60, 58)] = s116;
        dq[(60, 60)] = s121;
        dq[(60, 62)] = s123;
        dq[(61, 59)] = s116;
        dq[(61, 61)] = s121;
        dq[(61, 63)] = s123;
        dq[(62, 60)] = s120;
        dq[(62, 62)] = s125;
        dq[(62, 64)] = s127;
        dq[(63, 61)] = s120;
        dq[(63, 63)] = s125;
        dq[(63, 65)] = s127;
        dq[(64, 62)] = s124;
        dq[(64, 64)] = s129;
        dq[(64, 66)] = s131;
        dq[(65, 63)] = s124;
        dq[(65, 65)] = s129;
        dq[(65, 67)] = s131;
        dq[(66, 64)] = s128;
        dq[(66, 66)] = s133;
        dq[(66, 68)] = s135;
        dq[(67, 65)] = s128;
        dq[(67, 67)] = s133;
        dq[(67, 69)] = s135;
        dq[(68, 66)] = s132;
        dq[(68, 68)] = s137;
        dq[(68, 70)] = s139;
        dq[(69, 67)] = s132;
        dq[(69, 69)] = s137;
        dq[(69, 71)] = s139;
        dq[(70, 68)] = s136;
        dq[(70, 70)] = s141;
        dq[(70, 72)] = s143;
        dq[(71, 69)] = s136;
        dq[(71, 71)] = s141;
        dq[(71, 73)] = s143;
        dq[(72, 70)] = s140;
        dq[(72, 72)] = s145;
        dq[(72, 74)] = s147;
        dq[(73, 71)] = s140;
        dq[(73, 73)] = s145;
        dq[(73, 75)] = s147;
        dq[(74, 72)] = s144;
        dq[(74, 74)] = s149;
        dq[(74, 76)] = s151;
        dq[(75, 73)] = s144;
        dq[(75, 75)] = s149;
        dq[(75, 77)] = s151;
        dq[(76, 74)] = s148;
        dq[(76, 76)] = s153;
        dq[(76, 78)] = s155;
        dq[(77, 75)] = s148;
        dq[(77, 77)] = s153;
        dq[(77, 79)] = s155;
        dq[(78, 76)] = s152;
        dq[(78, 78)] = s157;
        dq[(78, 80)] = s159;
        dq[(79, 77)] = s152;
        dq[(79, 79)] = s157;
        dq[(79, 81)] = s159;
        dq[(80, 78)] = s156;
        dq[(80, 80)] = s161;
        dq[(80, 82)] = s163;
        dq[(81, 79)] = s156;
        dq[(81, 81)] = s161;
        dq[(81, 83)] = s163;
        dq[(82, 80)] = s160;
        dq[(82, 82)] = s165;
        dq[(82, 84)] = s167;
        dq[(83, 81)] = s160;
        dq[(83, 83)] = s165;
        dq[(83, 85)] = s167;
        dq[(84, 82)] = s164;
        dq[(84, 84)] = s169;
        dq[(84, 86)] = s171;
        dq[(85, 83)] = s164;
        dq[(85, 85)] = s169;
        dq[(85, 87)] = s171;
        dq[(86, 84)] = s168;
        dq[(86, 86)] = s173;
        dq[(86, 88)] = s175;
        dq[(87, 85)] = s168;
        dq[(87, 87)] = s173;
        dq[(87, 89)] = s175;
        dq[(88, 86)] = s172;
        dq[(88, 88)] = s177;
        dq[(88, 90)] = s179;
        dq[(89, 87)] = s172;
        dq[(89, 89)] = s177;
        dq[(89, 91)] = s179;
        dq[(90, 88)] = s176;
        dq[(90, 90)] = s181;
        dq[(90, 92)] = s183;
        dq[(91, 89)] = s176;
        dq[(91, 91)] = s181;
        dq[(91, 93)] = s183;
        dq[(92, 90)] = s180;
        dq[(92, 92)] = s185;
        dq[(92, 94)] = s187;
        dq[(93, 91)] = s180;
        dq[(93, 93)] = s185;
        dq[(93, 95)] = s187;
        dq[(94, 92)] = s184;
        dq[(94, 94)] = s189;
        dq[(94, 96)] = s191;
        dq[(95, 93)] = s184;
        dq[(95, 95)] = s189;
        dq[(95, 97)] = s191;
        dq[(96, 94)] = s188;
        dq[(96, 96)] = s193;
        dq[(96, 98)] = s195;
        dq[(97, 95)] = s188;
        dq[(97, 97)] = s193;
        dq[(97, 99)] = s195;
        dq[(98, 96)] = s192;
        dq[(98, 98)] = s197;
        dq[(98, 100)] = s199;
        dq[(99, 97)] = s192;
        dq[(99, 99)] = s197;
        dq[(99, 101)] = s199;
        dq[(100, 98)] = s196;
        dq[(100, 100)] = s201;
        dq[(100, 102)] = s203;
        dq[(101, 99)] = s196;
        dq[(101, 101)] = s201;
        dq[(101, 103)] = s203;
        dq[(102, 100)] = s200;
        dq[(102, 102)] = s205;
        dq[(102, 104)] = s207;
        dq[(103, 101)] = s200;
        dq[(103, 103)] = s205;
        dq[(103, 105)] = s207;
        dq[(104, 102)] = s204;
        dq[(104, 104)] = s209;
        dq[(104, 106)] = s211;
        dq[(105, 103)] = s204;
        dq[(105, 105)] = s209;
        dq[(105, 107)] = s211;
        dq[(106, 104)] = s208;
        dq[(106, 106)] = s213;
        dq[(106, 108)] = s215;
        dq[(107, 105)] = s208;
        dq[(107, 107)] = s213;
        dq[(107, 109)] = s215;
        dq[(108, 106)] = s212;
        dq[(108, 108)] = s217;
        dq[(108, 110)] = s219;
        dq[(109, 107)] = s212;
        dq[(109, 109)] = s217;
        dq[(109, 111)] = s219;
        dq[(110, 108)] = s216;
        dq[(110, 110)] = s221;
        dq[(110, 112)] = s223;
        dq[(111, 109)] = s216;
        dq[(111, 111)] = s221;
        dq[(111, 113)] = s223;
        dq[(112, 110)] = s220;
        dq[(112, 112)] = s225;
        dq[(112, 114)] = s227;
        dq[(113, 111)] = s220;
        dq[(113, 113)] = s225;
        dq[(113, 115)] = s227;
        dq[(114, 112)] = s224;
        dq[(114, 114)] = s229;
        dq[(114, 116)] = s231;
        dq[(115, 113)] = s224;
        dq[(115, 115)] = s229;
        dq[(115, 117)] = s231;
        dq[(116, 114)] = s228;
        dq[(116, 116)] = s233;
        dq[(116, 118)] = s235;
        dq[(117, 115)] = s228;
        dq[(117, 117)] = s233;
        dq[(117, 119)] = s235;
        dq[(118, 116)] = s232;
        dq[(118, 118)] = s237;
        dq[(118, 120)] = s239;
        dq[(119, 117)] = s232;
        dq[(119, 119)] = s237;
        dq[(119, 121)] = s239;
        dq[(120, 118)] = s236;
        dq[(120, 120)] = s241;
        dq[(120, 122)] = s243;
        dq[(121, 119)] = s236;
        dq[(121, 121)] = s241;
        dq[(121, 123)] = s243;
        dq[(122, 120)] = s240;
        dq[(122, 122)] = s245;
        dq[(122, 124)] = s247;
        dq[(123, 121)] = s240;
        dq[(123, 123)] = s245;
        dq[(123, 125)] = s247;
        dq[(124, 122)] = s244;
        dq[(124, 124)] = s249;
        dq[(124, 126)] = s251;
        dq[(125, 123)] = s244;
        dq[(125, 125)] = s249;
        dq[(125, 127)] = s251;
        dq[(126, 124)] = s248;
        dq[(126, 126)] = s253;
        dq[(126, 128)] = s255;
        dq[(127, 125)] = s248;
        dq[(127, 127)] = s253;
        dq[(127, 129)] = s255;
        dq[(128, 126)] = s252;
        dq[(128, 128)] = s257;
        dq[(128, 130)] = s259;
        dq[(129, 127)] = s252;
        dq[(129, 129)] = s257;
        dq[(129, 131)] = s259;
        dq[(130, 128)] = s256;
        dq[(130, 130)] = s261;
        dq[(130, 132)] = s263;
        dq[(131, 129)] = s256;
        dq[(131, 131)] = s261;
        dq[(131, 133)] = s263;
        dq[(132, 130)] = s260;
        dq[(132, 132)] = s265;
        dq[(132, 134)] = s267;
        dq[(133, 131)] = s260;
        dq[(133, 133)] = s265;
        dq[(133, 135)] = s267;
        dq[(134, 132)] = s264;
        dq[(134, 134)] = s269;
        dq[(134, 136)] = s271;
        dq[(135, 133)] = s264;
        dq[(135, 135)] = s269;
        dq[(135, 137)] = s271;
        dq[(136, 134)] = s268;
        dq[(136, 136)] = s273;
        dq[(136, 138)] = s275;
        dq[(137, 135)] = s268;
        dq[(137, 137)] = s273;
        dq[(137, 139)] = s275;
        dq[(138, 136)] = s272;
        dq[(138, 138)] = s277;
        dq[(138, 140)] = s279;
        dq[(139, 137)] = s272;
        dq[(139, 139)] = s277;
        dq[(139, 141)] = s279;
        dq[(140, 138)] = s276;
        dq[(140, 140)] = s281;
        dq[(140, 142)] = s283;
        dq[(141, 139)] = s276;
        dq[(141, 141)] = s281;
        dq[(141, 143)] = s283;
        dq[(142, 140)] = s280;
        dq[(142, 142)] = s285;
        dq[(142, 144)] = s287;
        dq[(143, 141)] = s280;
        dq[(143, 143)] = s285;
        dq[(143, 145)] = s287;
        dq[(144, 142)] = s284;
        dq[(144, 144)] = s289;
        dq[(144, 146)] = s291;
        dq[(145, 143)] = s284;
        dq[(145, 145)] = s289;
        dq[(145, 147)] = s291;
        dq[(146, 144)] = s288;
        dq[(146, 146)] = s293;
        dq[(146, 148)] = s295;
        dq[(147, 145)] = s288;
        dq[(147, 147)] = s293;
        dq[(147, 149)] = s295;
        dq[(148, 146)] = s292;
        dq[(148, 148)] = s297;
        dq[(148, 150)] = s299;
        dq[(149, 147)] = s292;
        dq[(149, 149)] = s297;
        dq[(149, 151)] = s299;
        dq[(150, 148)] = s296;
        dq[(150, 150)] = s301;
        dq[(150, 152)] = s303;
        dq[(151, 149)] = s296;
        dq[(151, 151)] = s301;
        dq[(151, 153)] = s303;
        dq[(152, 150)] = s300;
        dq[(152, 152)] = s305;
        dq[(152, 154)] = s307;
        dq[(153, 151)] = s300;
        dq[(153, 153)] = s305;
        dq[(153, 155)] = s307;
        dq[(154, 152)] = s304;
        dq[(154, 154)] = s309;
        dq[(154, 156)] = s311;
        dq[(155, 153)] = s304;
        dq[(155, 155)] = s309;
        dq[(155, 157)] = s311;
        dq[(156, 154)] = s308;
        dq[(156, 156)] = s313;
        dq[(156, 158)] = s315;
        dq[(157, 155)] = s308;
        dq[(157, 157)] = s313;
        dq[(157, 159)] = s315;
        dq[(158, 156)] = s312;
        dq[(158, 158)] = s317;
        dq[(158, 160)] = s319;
        dq[(159, 157)] = s312;
        dq[(159, 159)] = s317;
        dq[(159, 161)] = s319;
        dq[(160, 158)] = s316;
        dq[(160, 160)] = s321;
        dq[(160, 162)] = s323;
        dq[(161, 159)] = s316;
        dq[(161, 161)] = s321;
        dq[(161, 163)] = s323;
        dq[(162, 160)] = s320;
        dq[(162, 162)] = s325;
        dq[(162, 164)] = s327;
        dq[(163, 161)] = s320;
        dq[(163, 163)] = s325;
        dq[(163, 165)] = s327;
        dq[(164, 162)] = s324;
        dq[(164, 164)] = s329;
        dq[(164, 166)] = s331;
        dq[(165, 163)] = s324;
        dq[(165, 165)] = s329;
        dq[(165, 167)] = s331;
        dq[(166, 164)] = s328;
        dq[(166, 166)] = s333;
        dq[(166, 168)] = s335;
        dq[(167, 165)] = s328;
        dq[(167, 167)] = s333;
        dq[(167, 169)] = s335;
        dq[(168, 166)] = s332;
        dq[(168, 168)] = s337;
        dq[(168, 170)] = s339;
        dq[(169, 167)] = s332;
        dq[(169, 169)] = s337;
        dq[(169, 171)] = s339;
        dq[(170, 168)] = s336;
        dq[(170, 170)] = s341;
        dq[(170, 172)] = s343;
        dq[(171, 169)] = s336;
        dq[(171, 171)] = s341;
        dq[(171, 173)] = s343;
        dq[(172, 170)] = s340;
        dq[(172, 172)] = s345;
        dq[(172, 174)] = s347;
        dq[(173, 171)] = s340;
        dq[(173, 173)] = s345;
        dq[(173, 175)] = s347;
        dq[(174, 172)] = s344;
        dq[(174, 174)] = s349;
        dq[(174, 176)] = s351;
        dq[(175, 173)] = s344;
        dq[(175, 175)] = s349;
        dq[(175, 177)] = s351;
        dq[(176, 174)] = s348;
        dq[(176, 176)] = s353;
        dq[(176, 178)] = s355;
        dq[(177, 175)] = s348;
        dq[(177, 177)] = s353;
        dq[(177, 179)] = s355;
        dq[(178, 176)] = s352;
        dq[(178, 178)] = s357;
        dq[(178, 180)] = s359;
        dq[(179, 177)] = s352;
        dq[(179, 179)] = s357;
        dq[(179, 181)] = s359;
        dq[(180, 178)] = s356;
        dq[(180, 180)] = s361;
        dq[(180, 182)] = s363;
        dq[(181, 179)] = s356;
        dq[(181, 181)] = s361;
        dq[(181, 183)] = s363;
        dq[(182, 180)] = s360;
        dq[(182, 182)] = s365;
        dq[(182, 184)] = s367;
        dq[(183, 181)] = s360;
        dq[(183, 183)] = s365;
        dq[(183, 185)] = s367;
        dq[(184, 182)] = s364;
        dq[(184, 184)] = s369;
        dq[(184, 186)] = s371;
        dq[(185, 183)] = s364;
        dq[(185, 185)] = s369;
        dq[(185, 187)] = s371;
        dq[(186, 184)] = s368;
        dq[(186, 186)] = s373;
        dq[(186, 188)] = s375;
        dq[(187, 185)] = s368;
        dq[(187, 187)] = s373;
        dq[(187, 189)] = s375;
        dq[(188, 186)] = s372;
        dq[(188, 188)] = s377;
        dq[(188, 190)] = s379;
        dq[(189, 187)] = s372;
        dq[(189, 189)] = s377;
        dq[(189, 191)] = s379;
        dq[(190, 188)] = s376;
        dq[(190, 190)] = s381;
        dq[(190, 192)] = s383;
        dq[(191, 189)] = s376;
        dq[(191, 191)] = s381;
        dq[(191, 193)] = s383;
        dq[(192, 190)] = s380;
        dq[(192, 192)] = s385;
        dq[(192, 194)] = s387;
        dq[(193, 191)] = s380;
        dq[(193, 193)] = s385;
        dq[(193, 195)] = s387;
        dq[(194, 192)] = s384;
        dq[(194, 194)] = s389;
        dq[(194, 196)] = s391;
        dq[(195, 193)] = s384;
        dq[(195, 195)] = s389;
        dq[(195, 197)] = s391;
        dq[(196, 194)] = s388;
        dq[(196, 196)] = s393;
        dq[(196, 198)] = s395;
        dq[(197, 195)] = s388;
        dq[(197, 197)] = s393;
        dq[(197, 199)] = s395;
        dq[(198, 196)] = s392;
        dq[(198, 198)] = s394;
        dq[(199, 197)] = s392;
        dq[(199, 199)] = s394;
        (dq, dv)
    }
    #[inline]
    fn constraint_jacobian_nonzeros(
        &self,
        q: &::zeitner::__private::Vector<200>,
        v: &::zeitner::__private::Vector<200>,
        t: ::zeitner::__private::Float,
        values: &mut [::zeitner::__private::Float],
    ) {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let s0 = 2.0 * (q[2] - q[0]);
        let s1 = 2.0 * (q[3] - q[1]);
        let s2 = 2.0 * (q[4] - q[2]);
        let s3 = 2.0 * (q[5] - q[3]);
        let s4 = 2.0 * (q[6] - q[4]);
        let s5 = 2.0 * (q[7] - q[5]);
        let s6 = 2.0 * (q[8] - q[6]);
        let s7 = 2.0 * (q[9] - q[7]);
        let s8 = 2.0 * (q[10] - q[8]);
        let s9 = 2.0 * (q[11] - q[9]);
        let s10 = 2.0 * (q[12] - q[10]);
        let s11 = 2.0 * (q[13] - q[11]);
        let s12 = 2.0 * (q[14] - q[12]);
        let s13 = 2.0 * (q[15] - q[13]);
        let s14 = 2.0 * (q[16] - q[14]);
        let s15 = 2.0 * (q[17] - q[15]);
        let s16 = 2.0 * (q[18] - q[16]);
        let s17 = 2.0 * (q[19] - q[17]);
        let s18 = 2.0 * (q[20] - q[18]);
        let s19 = 2.0 * (q[21] - q[19]);
        let s20 = 2.0 * (q[22] - q[20]);
        let s21 = 2.0 * (q[23] - q[21]);
        let s22 = 2.0 * (q[24] - q[22]);
        let s23 = 2.0 * (q[25] - q[23]);
        let s24 = 2.0 * (q[26] - q[24]);
        let s25 = 2.0 * (q[27] - q[25]);
        let s26 = 2.0 * (q[28] - q[26]);
        let s27 = 2.0 * (q[29] - q[27]);
        let s28 = 2.0 * (q[30] - q[28]);
        let s29 = 2.0 * (q[31] - q[29]);
        let s30 = 2.0 * (q[32] - q[30]);
        let s31 = 2.0 * (q[33] - q[31]);
        let s32 = 2.0 * (q[34] - q[32]);
        let s33 = 2.0 * (q[35] - q[33]);
        let s34 = 2.0 * (q[36] - q[34]);
        let s35 = 2.0 * (q[37] - q[35]);
        let s36 = 2.0 * (q[38] - q[36]);
        let s37 = 2.0 * (q[39] - q[37]);
        let s38 = 2.0 * (q[40] - q[38]);
        let s39 = 2.0 * (q[41] - q[39]);
        let s40 = 2.0 * (q[42] - q[40]);
        let s41 = 2.0 * (q[43] - q[41]);
        let s42 = 2.0 * (q[44] - q[42]);
        let s43 = 2.0 * (q[45] - q[43]);
        let s44 = 2.0 * (q[46] - q[44]);
        let s45 = 2.0 * (q[47] - q[45]);
        let s46 = 2.0 * (q[48] - q[46]);
        let s47 = 2.0 * (q[49] - q[47]);
        let s48 = 2.0 * (q[50] - q[48]);
        let s49 = 2.0 * (q[51] - q[49]);
        let s50 = 2.0 * (q[52] - q[50]);
        let s51 = 2.0 * (q[53] - q[51]);
        let s52 = 2.0 * (q[54] - q[52]);
        let s53 = 2.0 * (q[55] - q[53]);
        let s54 = 2.0 * (q[56] - q[54]);
        let s55 = 2.0 * (q[57] - q[55]);
        let s56 = 2.0 * (q[58] - q[56]);
        let s57 = 2.0 * (q[59] - q[57]);
        let s58 = 2.0 * (q[60] - q[58]);
        let s59 = 2.0 * (q[61] - q[59]);
        let s60 = 2.0 * (q[62] - q[60]);
        let s61 = 2.0 * (q[63] - q[61]);
        let s62 = 2.0 * (q[64] - q[62]);
        let s63 = 2.0 * (q[65] - q[63]);
        let s64 = 2.0 * (q[66] - q[64]);
        let s65 = 2.0 * (q[67] - q[65]);
        let s66 = 2.0 * (q[68] - q[66]);
        let s67 = 2.0 * (q[69] - q[67]);
        let s68 = 2.0 * (q[70] - q[68]);
        let s69 = 2.0 * (q[71] - q[69]);
        let s70 = 2.0 * (q[72] - q[70]);
        let s71 = 2.0 * (q[73] - q[71]);
        let s72 = 2.0 * (q[74] - q[72]);
        let s73 = 2.0 * (q[75] - q[73]);
        let s74 = 2.0 * (q[76] - q[74]);
        let s75 = 2.0 * (q[77] - q[75]);
        let s76 = 2.0 * (q[78] - q[76]);
        let s77 = 2.0 * (q[79] - q[77]);
        let s78 = 2.0 * (q[80] - q[78]);
        let s79 = 2.0 * (q[81] - q[79]);
        let s80 = 2.0 * (q[82] - q[80]);
        let s81 = 2.0 * (q[83] - q[81]);
        let s82 = 2.0 * (q[84] - q[82]);
        let s83 = 2.0 * (q[85] - q[83]);
        let s84 = 2.0 * (q[86] - q[84]);
        let s85 = 2.0 * (q[87] - q[85]);
        let s86 = 2.0 * (q[88] - q[86]);
        let s87 = 2.0 * (q[89] - q[87]);
        let s88 = 2.0 * (q[90] - q[88]);
        let s89 = 2.0 * (q[91] - q[89]);
        let s90 = 2.0 * (q[92] - q[90]);
        let s91 = 2.0 * (q[93] - q[91]);
        let s92 = 2.0 * (q[94] - q[92]);
        let s93 = 2.0 * (q[95] - q[93]);
        let s94 = 2.0 * (q[96] - q[94]);
        let s95 = 2.0 * (q[97] - q[95]);
        let s96 = 2.0 * (q[98] - q[96]);
        let s97 = 2.0 * (q[99] - q[97]);
        let s98 = 2.0 * (q[100] - q[98]);
        let s99 = 2.0 * (q[101] - q[99]);
        let s100 = 2.0 * (q[102] - q[100]);
        let s101 = 2.0 * (q[103] - q[101]);
        let s102 = 2.0 * (q[104] - q[102]);
        let s103 = 2.0 * (q[105] - q[103]);
        let s104 = 2.0 * (q[106] - q[104]);
        let s105 = 2.0 * (q[107] - q[105]);
        let s106 = 2.0 * (q[108] - q[106]);
        let s107 = 2.0 * (q[109] - q[107]);
        let s108 = 2.0 * (q[110] - q[108]);
        let s109 = 2.0 * (q[111] - q[109]);
        let s110 = 2.0 * (q[112] - q[110]);
        let s111 = 2.0 * (q[113] - q[111]);
        let s112 = 2.0 * (q[114] - q[112]);
        let s113 = 2.0 * (q[115] - q[113]);
        let s114 = 2.0 * (q[116] - q[114]);
        let s115 = 2.0 * (q[117] - q[115]);
        let s116 = 2.0 * (q[118] - q[116]);
        let s117 = 2.0 * (q[119] - q[117]);
        let s118 = 2.0 * (q[120] - q[118]);
        let s119 = 2.0 * (q[121] - q[119]);
        let s120 = 2.0 * (q[122] - q[120]);
        let s121 = 2.0 * (q[123] - q[121]);
        let s122 = 2.0 * (q[124] - q[122]);
        let s123 = 2.0 * (q[125] - q[123]);
        let s124 = 2.0 * (q[126] - q[124]);
        let s125 = 2.0 * (q[127] - q[125]);
        let s126 = 2.0 * (q[128] - q[126]);
        let s127 = 2.0 * (q[129] - q[127]);
        let s128 = 2.0 * (q[130] - q[128]);
        let s129 = 2.0 * (q[131] - q[129]);
        let s130 = 2.0 * (q[132] - q[130]);
        let s131 = 2.0 * (q[133] - q[131]);
        let s132 = 2.0 * (q[134] - q[132]);
        let s133 = 2.0 * (q[135] - q[133]);
        let s134 = 2.0 * (q[136] - q[134]);
        let s135 = 2.0 * (q[137] - q[135]);
        let s136 = 2.0 * (q[138] - q[136]);
        let s137 = 2.0 * (q[139] - q[137]);
        let s138 = 2.0 * (q[140] - q[138]);
        let s139 = 2.0 * (q[141] - q[139]);
        let s140 = 2.0 * (q[142] - q[140]);
        let s141 = 2.0 * (q[143] - q[141]);
        let s142 = 2.0 * (q[144] - q[142]);
        let s143 = 2.0 * (q[145] - q[143]);
        let s144 = 2.0 * (q[146] - q[144]);
        let s145 = 2.0 * (q[147] - q[145]);
        let s146 = 2.0 * (q[148] - q[146]);
        let s147 = 2.0 * (q[149] - q[147]);
        let s148 = 2.0 * (q[150] - q[148]);
        let s149 = 2.0 * (q[151] - q[149]);
        let s150 = 2.0 * (q[152] - q[150]);
        let s151 = 2.0 * (q[153] - q[151]);
        let s152 = 2.0 * (q[154] - q[152]);
        let s153 = 2.0 * (q[155] - q[153]);
        let s154 = 2.0 * (q[156] - q[154]);
        let s155 = 2.0 * (q[157] - q[155]);
        let s156 = 2.0 * (q[158] - q[156]);
        let s157 = 2.0 * (q[159] - q[157]);
        let s158 = 2.0 * (q[160] - q[158]);
        let s159 = 2.0 * (q[161] - q[159]);
        let s160 = 2.0 * (q[162] - q[160]);
        let s161 = 2.0 * (q[163] - q[161]);
        let s162 = 2.0 * (q[164] - q[162]);
        let s163 = 2.0 * (q[165] - q[163]);
        let s164 = 2.0 * (q[166] - q[164]);
        let s165 = 2.0 * (q[167] - q[165]);
        let s166 = 2.0 * (q[168] - q[166]);
        let s167 = 2.0 * (q[169] - q[167]);
        let s168 = 2.0 * (q[170] - q[168]);
        let s169 = 2.0 * (q[171] - q[169]);
        let s170 = 2.0 * (q[172] - q[170]);
        let s171 = 2.0 * (q[173] - q[171]);
        let s172 = 2.0 * (q[174] - q[172]);
        let s173 = 2.0 * (q[175] - q[173]);
        let s174 = 2.0 * (q[176] - q[174]);
        let s175 = 2.0 * (q[177] - q[175]);
        let s176 = 2.0 * (q[178] - q[176]);
        let s177 = 2.0 * (q[179] - q[177]);
        let s178 = 2.0 * (q[180] - q[178]);
        let s179 = 2.0 * (q[181] - q[179]);
        let s180 = 2.0 * (q[182] - q[180]);
        let s181 = 2.0 * (q[183] - q[181]);
        let s182 = 2.0 * (q[184] - q[182]);
        let s183 = 2.0 * (q[185] - q[183]);
        let s184 = 2.0 * (q[186] - q[184]);
        let s185 = 2.0 * (q[187] - q[185]);
        let s186 = 2.0 * (q[188] - q[186]);
        let s187 = 2.0 * (q[189] - q[187]);
        let s188 = 2.0 * (q[190] - q[188]);
        let s189 = 2.0 * (q[191] - q[189]);
        let s190 = 2.0 * (q[192] - q[190]);
        let s191 = 2.0 * (q[193] - q[191]);
        let s192 = 2.0 * (q[194] - q[192]);
        let s193 = 2.0 * (q[195] - q[193]);
        let s194 = 2.0 * (q[196] - q[194]);
        let s195 = 2.0 * (q[197] - q[195]);
        let s196 = 2.0 * (q[198] - q[196]);
        let s197 = 2.0 * (q[199] - q[197]);
        values[0] = 2.0 * q[0];
        values[1] = 2.0 * q[1];
        values[2] = -s0;
        values[3] = -s1;
        values[4] = s0;
        values[5] = s1;
        values[6] = -s2;
        values[7] = -s3;
        values[8] = s2;
        values[9] = s3;
        values[10] = -s4;
        values[11] = -s5;
        values[12] = s4;
        values[13] = s5;
        values[14] = -s6;
        values[15] = -s7;
        values[16] = s6;
        values[17] = s7;
        values[18] = -s8;
        values[19] = -s9;
        values[20] = s8;
        values[21] = s9;
        values[22] = -s10;
        values[23] = -s11;
        values[24] = s10;
        values[25] = s11;
        values[26] = -s12;
        values[27] = -s13;
        values[28] = s12;
        values[29] = s13;
        values[30] = -s14;
        values[31] = -s15;
        values[32] = s14;
        values[33] = s15;
        values[34] = -s16;
        values[35] = -s17;
        values[36] = s16;
        values[37] = s17;
        values[38] = -s18;
        values[39] = -s19;
        values[40] = s18;
        values[41] = s19;
        values[42] = -s20;
        values[43] = -s21;
        values[44] = s20;
        values[45] = s21;
        values[46] = -s22;
        values[47] = -s23;
        values[48] = s22;
        values[49] = s23;
        values[50] = -s24;
        values[51] = -s25;
        values[52] = s24;
        values[53] = s25;
        values[54] = -s26;
        values[55] = -s27;
        values[56] = s26;
        values[57] = s27;
        values[58] = -s28;
        values[59] = -s29;
        values[60] = s28;
        values[61] = s29;
        values[62] = -s30;
        values[63] = -s31;
        values[64] = s30;
        values[65] = s31;
        values[66] = -s32;
        values[67] = -s33;
        values[68] = s32;
        values[69] = s33;
        values[70] = -s34;
        values[71] = -s35;
        values[72] = s34;
        values[73] = s35;
        values[74] = -s36;
        values[75] = -s37;
        values[76] = s36;
        values[77] = s37;
        values[78] = -s38;
        values[79] = -s39;
        values[80] = s38;
        values[81] = s39;
        values[82] = -s40;
        values[83] = -s41;
        values[84] = s40;
        values[85] = s41;
        values[86] = -s42;
        values[87] = -s43;
        values[88] = s42;
        values[89] = s43;
        values[90] = -s44;
        values[91] = -s45;
        values[92] = s44;
        values[93] = s45;
        values[94] = -s46;
        values[95] = -s47;
        values[96] = s46;
        values[97] = s47;
        values[98] = -s48;
        values[99] = -s49;
        values[100] = s48;
        values[101] = s49;
        values[102] = -s50;
        values[103] = -s51;
        values[104] = s50;
        values[105] = s51;
        values[106] = -s52;
        values[107] = -s53;
        values[108] = s52;
        values[109] = s53;
        values[110] = -s54;
        values[111] = -s55;
        values[112] = s54;
        values[113] = s55;
        values[114] = -s56;
        values[115] = -s57;
        values[116] = s56;
        values[117] = s57;
        values[118] = -s58;
        values[119] = -s59;
        values[120] = s58;
        values[121] = s59;
        values[122] = -s60;
        values[123] = -s61;
        values[124] = s60;
        values[125] = s61;
        values[126] = -s62;
        values[127] = -s63;
        values[128] = s62;
        values[129] = s63;
        values[130] = -s64;
        values[131] = -s65;
        values[132] = s64;
        values[133] = s65;
        values[134] = -s66;
        values[135] = -s67;
        values[136] = s66;
        values[137] = s67;
        values[138] = -s68;
        values[139] = -s69;
        values[140] = s68;
        values[141] = s69;
        values[142] = -s70;
        values[143] = -s71;
        values[144] = s70;
        values[145] = s71;
        values[146] = -s72;
        values[147] = -s73;
        values[148] = s72;
        values[149] = s73;
        values[150] = -s74;
        values[151] = -s75;
        values[152] = s74;
        values[153] = s75;
        values[154] = -s76;
        values[155] = -s77;
        values[156] = s76;
        values[157] = s77;
        values[158] = -s78;
        values[159] = -s79;
        values[160] = s78;
        values[161] = s79;
        values[162] = -s80;
        values[163] = -s81;
        values[164] = s80;
        values[165] = s81;
        values[166] = -s82;
        values[167] = -s83;
        values[168] = s82;
        values[169] = s83;
        values[170] = -s84;
        values[171] = -s85;
        values[172] = s84;
        values[173] = s85;
        values[174] = -s86;
        values[175] = -s87;
        values[176] = s86;
        values[177] = s87;
        values[178] = -s88;
        values[179] = -s89;
        values[180] = s88;
        values[181] = s89;
        values[182] = -s90;
        values[183] = -s91;
        values[184] = s90;
        values[185] = s91;
        values[186] = -s92;
        values[187] = -s93;
        values[188] = s92;
        values[189] = s93;
        values[190] = -s94;
        values[191] = -s95;
        values[192] = s94;
        values[193] = s95;
        values[194] = -s96;
        values[195] = -s97;
        values[196] = s96;
        values[197] = s97;
        values[198] = -s98;
        values[199] = -s99;
        values[200] = s98;
        values[201] = s99;
        values[202] = -s100;
        values[203] = -s101;
        values[204] = s100;
        values[205] = s101;
        values[206] = -s102;
        values[207] = -s103;
        values[208] = s102;
        values[209] = s103;
        values[210] = -s104;
        values[211] = -s105;
        values[212] = s104;
        values[213] = s105;
        values[214] = -s106;
        values[215] = -s107;
        values[216] = s106;
        values[217] = s107;
        values[218] = -s108;
        values[219] = -s109;
        values[220] = s108;
        values[221] = s109;
        values[222] = -s110;
        values[223] = -s111;
        values[224] = s110;
        values[225] = s111;
        values[226] = -s112;
        values[227] = -s113;
        values[228] = s112;
        values[229] = s113;
        values[230] = -s114;
        values[231] = -s115;
        values[232] = s114;
        values[233] = s115;
        values[234] = -s116;
        values[235] = -s117;
        values[236] = s116;
        values[237] = s117;
        values[238] = -s118;
        values[239] = -s119;
        values[240] = s118;
        values[241] = s119;
        values[242] = -s120;
        values[243] = -s121;
        values[244] = s120;
        values[245] = s121;
        values[246] = -s122;
        values[247] = -s123;
        values[248] = s122;
        values[249] = s123;
        values[250] = -s124;
        values[251] = -s125;
        values[252] = s124;
        values[253] = s125;
        values[254] = -s126;
        values[255] = -s127;
        values[256] = s126;
        values[257] = s127;
        values[258] = -s128;
        values[259] = -s129;
        values[260] = s128;
        values[261] = s129;
        values[262] = -s130;
        values[263] = -s131;
        values[264] = s130;
        values[265] = s131;
        values[266] = -s132;
        values[267] = -s133;
        values[268] = s132;
        values[269] = s133;
        values[270] = -s134;
        values[271] = -s135;
        values[272] = s134;
        values[273] = s135;
        values[274] = -s136;
        values[275] = -s137;
        values[276] = s136;
        values[277] = s137;
        values[278] = -s138;
        values[279] = -s139;
        values[280] = s138;
        values[281] = s139;
        values[282] = -s140;
        values[283] = -s141;
        values[284] = s140;
        values[285] = s141;
        values[286] = -s142;
        values[287] = -s143;
        values[288] = s142;
        values[289] = s143;
        values[290] = -s144;
        values[291] = -s145;
        values[292] = s144;
        values[293] = s145;
        values[294] = -s146;
        values[295] = -s147;
        values[296] = s146;
        values[297] = s147;
        values[298] = -s148;
        values[299] = -s149;
        values[300] = s148;
        values[301] = s149;
        values[302] = -s150;
        values[303] = -s151;
        values[304] = s150;
        values[305] = s151;
        values[306] = -s152;
        values[307] = -s153;
        values[308] = s152;
        values[309] = s153;
        values[310] = -s154;
        values[311] = -s155;
        values[312] = s154;
        values[313] = s155;
        values[314] = -s156;
        values[315] = -s157;
        values[316] = s156;
        values[317] = s157;
        values[318] = -s158;
        values[319] = -s159;
        values[320] = s158;
        values[321] = s159;
        values[322] = -s160;
        values[323] = -s161;
        values[324] = s160;
        values[325] = s161;
        values[326] = -s162;
        values[327] = -s163;
        values[328] = s162;
        values[329] = s163;
        values[330] = -s164;
        values[331] = -s165;
        values[332] = s164;
        values[333] = s165;
        values[334] = -s166;
        values[335] = -s167;
        values[336] = s166;
        values[337] = s167;
        values[338] = -s168;
        values[339] = -s169;
        values[340] = s168;
        values[341] = s169;
        values[342] = -s170;
        values[343] = -s171;
        values[344] = s170;
        values[345] = s171;
        values[346] = -s172;
        values[347] = -s173;
        values[348] = s172;
        values[349] = s173;
        values[350] = -s174;
        values[351] = -s175;
        values[352] = s174;
        values[353] = s175;
        values[354] = -s176;
        values[355] = -s177;
        values[356] = s176;
        values[357] = s177;
        values[358] = -s178;
        values[359] = -s179;
        values[360] = s178;
        values[361] = s179;
        values[362] = -s180;
        values[363] = -s181;
        values[364] = s180;
        values[365] = s181;
        values[366] = -s182;
        values[367] = -s183;
        values[368] = s182;
        values[369] = s183;
        values[370] = -s184;
        values[371] = -s185;
        values[372] = s184;
        values[373] = s185;
        values[374] = -s186;
        values[375] = -s187;
        values[376] = s186;
        values[377] = s187;
        values[378] = -s188;
        values[379] = -s189;
        values[380] = s188;
        values[381] = s189;
        values[382] = -s190;
        values[383] = -s191;
        values[384] = s190;
        values[385] = s191;
        values[386] = -s192;
        values[387] = -s193;
        values[388] = s192;
        values[389] = s193;
        values[390] = -s194;
        values[391] = -s195;
        values[392] = s194;
        values[393] = s195;
        values[394] = -s196;
        values[395] = -s197;
        values[396] = s196;
        values[397] = s197;
    }
    #[inline]
    fn force_jacobian_nonzeros(
        &self,
        q: &::zeitner::__private::Vector<200>,
        v: &::zeitner::__private::Vector<200>,
        t: ::zeitner::__private::Float,
        values: &mut [::zeitner::__private::Float],
    ) {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
    }
    #[inline]
    fn constraint_force_jacobian_nonzeros(
        &self,
        q: &::zeitner::__private::Vector<200>,
        v: &::zeitner::__private::Vector<200>,
        t: ::zeitner::__private::Float,
        lambda: &::zeitner::__private::Vector<100>,
        values: &mut [::zeitner::__private::Float],
    ) {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let s0 = -2.0 * lambda[1];
        let s1 = 2.0 * lambda[0] - s0;
        let s2 = 2.0 * lambda[1];
        let s3 = -s2;
        let s4 = -2.0 * lambda[2];
        let s5 = s2 - s4;
        let s6 = 2.0 * lambda[2];
        let s7 = -s6;
        let s8 = -2.0 * lambda[3];
        let s9 = s6 - s8;
        let s10 = 2.0 * lambda[3];
        let s11 = -s10;
        let s12 = -2.0 * lambda[4];
        let s13 = s10 - s12;
        let s14 = 2.0 * lambda[4];
        let s15 = -s14;
        let s16 = -2.0 * lambda[5];
        let s17 = s14 - s16;
        let s18 = 2.0 * lambda[5];
        let s19 = -s18;
        let s20 = -2.0 * lambda[6];
        let s21 = s18 - s20;
        let s22 = 2.0 * lambda[6];
        let s23 = -s22;
        let s24 = -2.0 * lambda[7];
        let s25 = s22 - s24;
        let s26 = 2.0 * lambda[7];
        let s27 = -s26;
        let s28 = -2.0 * lambda[8];
        let s29 = s26 - s28;
        let s30 = 2.0 * lambda[8];
        let s31 = -s30;
        let s32 = -2.0 * lambda[9];
        let s33 = s30 - s32;
        let s34 = 2.0 * lambda[9];
        let s35 = -s34;
        let s36 = -2.0 * lambda[10];
        let s37 = s34 - s36;
        let s38 = 2.0 * lambda[10];
        let s39 = -s38;
        let s40 = -2.0 * lambda[11];
        let s41 = s38 - s40;
        let s42 = 2.0 * lambda[11];
        let s43 = -s42;
        let s44 = -2.0 * lambda[12];
        let s45 = s42 - s44;
        let s46 = 2.0 * lambda[12];
        let s47 = -s46;
        let s48 = -2.0 * lambda[13];
        let s49 = s46 - s48;
        let s50 = 2.0 * lambda[13];
        let s51 = -s50;
        let s52 = -2.0 * lambda[14];
        let s53 = s50 - s52;
        let s54 = 2.0 * lambda[14];
        let s55 = -s54;
        let s56 = -2.0 * lambda[15];
        let s57 = s54 - s56;
        let s58 = 2.0 * lambda[15];
        let s59 = -s58;
        let s60 = -2.0 * lambda[16];
        let s61 = s58 - s60;
        let s62 = 2.0 * lambda[16];
        let s63 = -s62;
        let s64 = -2.0 * lambda[17];
        let s65 = s62 - s64;
        let s66 = 2.0 * lambda[17];
        let s67 = -s66;
        let s68 = -2.0 * lambda[18];
        let s69 = s66 - s68;
        let s70 = 2.0 * lambda[18];
        let s71 = -s70;
        let s72 = -2.0 * lambda[19];
        let s73 = s70 - s72;
        let s74 = 2.0 * lambda[19];
        let s75 = -s74;
        let s76 = -2.0 * lambda[20];
        let s77 = s74 - s76;
        let s78 = 2.0 * lambda[20];
        let s79 = -s78;
        let s80 = -2.0 * lambda[21];
        let s81 = s78 - s80;
        let s82 = 2.0 * lambda[21];
        let s83 = -s82;
        let s84 = -2.0 * lambda[22];
        let s85 = s82 - s84;
        let s86 = 2.0 * lambda[22];
        let s87 = -s86;
        let s88 = -2.0 * lambda[23];
        let s89 = s86 - s88;
        let s90 = 2.0 * lambda[23];
        let s91 = -s90;
        let s92 = -2.0 * lambda[24];
        let s93 = s90 - s92;
        let s94 = 2.0 * lambda[24];
        let s95 = -s94;
        let s96 = -2.0 * lambda[25];
        let s97 = s94 - s96;
        let s98 = 2.0 * lambda[25];
        let s99 = -s98;
        let s100 = -2.0 * lambda[26];
        let s101 = s98 - s100;
        let s102 = 2.0 * lambda[26];
        let s103 = -s102;
        let s104 = -2.0 * lambda[27];
        let s105 = s102 - s104;
        let s106 = 2.0 * lambda[27];
        let s107 = -s106;
        let s108 = -2.0 * lambda[28];
        let s109 = s106 - s108;
        let s110 = 2.0 * lambda[28];
        let s111 = -s110;
        let s112 = -2.0 * lambda[29];
        let s113 = s110 - s112;
        let s114 = 2.0 * lambda[29];
        let s115 = -s114;
        let s116 = -2.0 * lambda[30];
        let s117 = s114 - s116;
        let s118 = 2.0 * lambda[30];
        let s119 = -s118;
        let s120 = -2.0 * lambda[31];
        let s121 = s118 - s120;
        let s122 = 2.0 * lambda[31];
        let s123 = -s122;
        let s124 = -2.0 * lambda[32];
        let s125 = s122 - s124;
        let s126 = 2.0 * lambda[32];
        let s127 = -s126;
        let s128 = -2.0 * lambda[33];
        let s129 = s126 - s128;
        let s130 = 2.0 * lambda[33];
        let s131 = -s130;
        let s132 = -2.0 * lambda[34];
        let s133 = s130 - s132;
        let s134 = 2.0 * lambda[34];
        let s135 = -s134;
        let s136 = -2.0 * lambda[35];
        let s137 = s134 - s136;
        let s138 = 2.0 * lambda[35];
        let s139 = -s138;
        let s140 = -2.0 * lambda[36];
        let s141 = s138 - s140;
        let s142 = 2.0 * lambda[36];
        let s143 = -s142;
        let s144 = -2.0 * lambda[37];
        let s145 = s142 - s144;
        let s146 = 2.0 * lambda[37];
        let s147 = -s146;
        let s148 = -2.0 * lambda[38];
        let s149 = s146 - s148;
        let s150 = 2.0 * lambda[38];
        let s151 = -s150;
        let s152 = -2.0 * lambda[39];
        let s153 = s150 - s152;
        let s154 = 2.0 * lambda[39];
        let s155 = -s154;
        let s156 = -2.0 * lambda[40];
        let s157 = s154 - s156;
        let s158 = 2.0 * lambda[40];
        let s159 = -s158;
        let s160 = -2.0 * lambda[41];
        let s161 = s158 - s160;
        let s162 = 2.0 * lambda[41];
        let s163 = -s162;
        let s164 = -2.0 * lambda[42];
        let s165 = s162 - s164;
        let s166 = 2.0 * lambda[42];
        let s167 = -s166;
        let s168 = -2.0 * lambda[43];
        let s169 = s166 - s168;
        let s170 = 2.0 * lambda[43];
        let s171 = -s170;
        let s172 = -2.0 * lambda[44];
        let s173 = s170 - s172;
        let s174 = 2.0 * lambda[44];
        let s175 = -s174;
        let s176 = -2.0 * lambda[45];
        let s177 = s174 - s176;
        let s178 = 2.0 * lambda[45];
        let s179 = -s178;
        let s180 = -2.0 * lambda[46];
        let s181 = s178 - s180;
        let s182 = 2.0 * lambda[46];
        let s183 = -s182;
        let s184 = -2.0 * lambda[47];
        let s185 = s182 - s184;
        let s186 = 2.0 * lambda[47];
        let s187 = -s186;
        let s188 = -2.0 * lambda[48];
        let s189 = s186 - s188;
        let s190 = 2.0 * lambda[48];
        let s191 = -s190;
        let s192 = -2.0 * lambda[49];
        let s193 = s190 - s192;
        let s194 = 2.0 * lambda[49];
        let s195 = -s194;
        let s196 = -2.0 * lambda[50];
        let s197 = s194 - s196;
        let s198 = 2.0 * lambda[50];
        let s199 = -s198;
        let s200 = -2.0 * lambda[51];
        let s201 = s198 - s200;
        let s202 = 2.0 * lambda[51];
        let s203 = -s202;
        let s204 = -2.0 * lambda[52];
        let s205 = s202 - s204;
        let s206 = 2.0 * lambda[52];
        let s207 = -s206;
        let s208 = -2.0 * lambda[53];
        let s209 = s206 - s208;
        let s210 = 2.0 * lambda[53];
        let s211 = -s210;
        let s212 = -2.0 * lambda[54];
        let s213 = s210 - s212;
        let s214 = 2.0 * lambda[54];
        let s215 = -s214;
        let s216 = -2.0 * lambda[55];
        let s217 = s214 - s216;
        let s218 = 2.0 * lambda[55];
        let s219 = -s218;
        let s220 = -2.0 * lambda[56];
        let s221 = s218 - s220;
        let s222 = 2.0 * lambda[56];
        let s223 = -s222;
        let s224 = -2.0 * lambda[57];
        let s225 = s222 - s224;
        let s226 = 2.0 * lambda[57];
        let s227 = -s226;
        let s228 = -2.0 * lambda[58];
        let s229 = s226 - s228;
        let s230 = 2.0 * lambda[58];
        let s231 = -s230;
        let s232 = -2.0 * lambda[59];
        let s233 = s230 - s232;
        let s234 = 2.0 * lambda[59];
        let s235 = -s234;
        let s236 = -2.0 * lambda[60];
        let s237 = s234 - s236;
        let s238 = 2.0 * lambda[60];
        let s239 = -s238;
        let s240 = -2.0 * lambda[61];
        let s241 = s238 - s240;
        let s242 = 2.0 * lambda[61];
        let s243 = -s242;
        let s244 = -2.0 * lambda[62];
        let s245 = s242 - s244;
        let s246 = 2.0 * lambda[62];
        let s247 = -s246;
        let s248 = -2.0 * lambda[63];
        let s249 = s246 - s248;
        let s250 = 2.0 * lambda[63];
        let s251 = -s250;
        let s252 = -2.0 * lambda[64];
        let s253 = s250 - s252;
        let s254 = 2.0 * lambda[64];
        let s255 = -s254;
        let s256 = -2.0 * lambda[65];
        let s257 = s254 - s256;
        let s258 = 2.0 * lambda[65];
        let s259 = -s258;
        let s260 = -2.0 * lambda[66];
        let s261 = s258 - s260;
        let s262 = 2.0 * lambda[66];
        let s263 = -s262;
        let s264 = -2.0 * lambda[67];
        let s265 = s262 - s264;
        let s266 = 2.0 * lambda[67];
        let s267 = -s266;
        let s268 = -2.0 * lambda[68];
        let s269 = s266 - s268;
        let s270 = 2.0 * lambda[68];
        let s271 = -s270;
        let s272 = -2.0 * lambda[69];
        let s273 = s270 - s272;
        let s274 = 2.0 * lambda[69];
        let s275 = -s274;
        let s276 = -2.0 * lambda[70];
        let s277 = s274 - s276;
        let s278 = 2.0 * lambda[70];
        let s279 = -s278;
        let s280 = -2.0 * lambda[71];
        let s281 = s278 - s280;
        let s282 = 2.0 * lambda[71];
        let s283 = -s282;
        let s284 = -2.0 * lambda[72];
        let s285 = s282 - s284;
        let s286 = 2.0 * lambda[72];
        let s287 = -s286;
        let s288 = -2.0 * lambda[73];
        let s289 = s286 - s288;
        let s290 = 2.0 * lambda[73];
        let s291 = -s290;
        let s292 = -2.0 * lambda[74];
        let s293 = s290 - s292;
        let s294 = 2.0 * lambda[74];
        let s295 = -s294;
        let s296 = -2.0 * lambda[75];
        let s297 = s294 - s296;
        let s298 = 2.0 * lambda[75];
        let s299 = -s298;
        let s300 = -2.0 * lambda[76];
        let s301 = s298 - s300;
        let s302 = 2.0 * lambda[76];
        let s303 = -s302;
        let s304 = -2.0 * lambda[77];
        let s305 = s302 - s304;
        let s306 = 2.0 * lambda[77];
        let s307 = -s306;
        let s308 = -2.0 * lambda[78];
        let s309 = s306 - s308;
        let s310 = 2.0 * lambda[78];
        let s311 = -s310;
        let s312 = -2.0 * lambda[79];
        let s313 = s310 - s312;
        let s314 = 2.0 * lambda[79];
        let s315 = -s314;
        let s316 = -2.0 * lambda[80];
        let s317 = s314 - s316;
        let s318 = 2.0 * lambda[80];
        let s319 = -s318;
        let s320 = -2.0 * lambda[81];
        let s321 = s318 - s320;
        let s322 = 2.0 * lambda[81];
        let s323 = -s322;
        let s324 = -2.0 * lambda[82];
        let s325 = s322 - s324;
        let s326 = 2.0 * lambda[82];
        let s327 = -s326;
        let s328 = -2.0 * lambda[83];
        let s329 = s326 - s328;
        let s330 = 2.0 * lambda[83];
        let s331 = -s330;
        let s332 = -2.0 * lambda[84];
        let s333 = s330 - s332;
        let s334 = 2.0 * lambda[84];
        let s335 = -s334;
        let s336 = -2.0 * lambda[85];
        let s337 = s334 - s336;
        let s338 = 2.0 * lambda[85];
        let s339 = -s338;
        let s340 = -2.0 * lambda[86];
        let s341 = s338 - s340;
        let s342 = 2.0 * lambda[86];
        let s343 = -s342;
        let s344 = -2.0 * lambda[87];
        let s345 = s342 - s344;
        let s346 = 2.0 * lambda[87];
        let s347 = -s346;
        let s348 = -2.0 * lambda[88];
        let s349 = s346 - s348;
        let s350 = 2.0 * lambda[88];
        let s351 = -s350;
        let s352 = -2.0 * lambda[89];
        let s353 = s350 - s352;
        let s354 = 2.0 * lambda[89];
        let s355 = -s354;
        let s356 = -2.0 * lambda[90];
        let s357 = s354 - s356;
        let s358 = 2.0 * lambda[90];
        let s359 = -s358;
        let s360 = -2.0 * lambda[91];
        let s361 = s358 - s360;
        let s362 = 2.0 * lambda[91];
        let s363 = -s362;
        let s364 = -2.0 * lambda[92];
        let s365 = s362 - s364;
        let s366 = 2.0 * lambda[92];
        let s367 = -s366;
        let s368 = -2.0 * lambda[93];
        let s369 = s366 - s368;
        let s370 = 2.0 * lambda[93];
        let s371 = -s370;
        let s372 = -2.0 * lambda[94];
        let s373 = s370 - s372;
        let s374 = 2.0 * lambda[94];
        let s375 = -s374;
        let s376 = -2.0 * lambda[95];
        let s377 = s374 - s376;
        let s378 = 2.0 * lambda[95];
        let s379 = -s378;
        let s380 = -2.0 * lambda[96];
        let s381 = s378 - s380;
        let s382 = 2.0 * lambda[96];
        let s383 = -s382;
        let s384 = -2.0 * lambda[97];
        let s385 = s382 - s384;
        let s386 = 2.0 * lambda[97];
        let s387 = -s386;
        let s388 = -2.0 * lambda[98];
        let s389 = s386 - s388;
        let s390 = 2.0 * lambda[98];
        let s391 = -s390;
        let s392 = -2.0 * lambda[99];
        let s393 = s390 - s392;
        let s394 = 2.0 * lambda[99];
        let s395 = -s394;
        values[0] = s1;
        values[1] = s3;
        values[2] = s1;
        values[3] = s3;
        values[4] = s0;
        values[5] = s5;
        values[6] = s7;
        values[7] = s0;
        values[8] = s5;
        values[9] = s7;
        values[10] = s4;
        values[11] = s9;
        values[12] = s11;
        values[13] = s4;
        values[14] = s9;
        values[15] = s11;
        values[16] = s8;
        values[17] = s13;
        values[18] = s15;
        values[19] = s8;
        values[20] = s13;
        values[21] = s15;
        values[22] = s12;
        values[23] = s17;
        values[24] = s19;
        values[25] = s12;
        values[26] = s17;
        values[27] = s19;
        values[28] = s16;
        values[29] = s21;
        values[30] = s23;
        values[31] = s16;
        values[32] = s21;
        values[33] = s23;
        values[34] = s20;
        values[35] = s25;
        values[36] = s27;
        values[37] = s20;
        values[38] = s25;
        values[39] = s27;
        values[40] = s24;
        values[41] = s29;
        values[42] = s31;
        values[43] = s24;
        values[44] = s29;
        values[45] = s31;
        values[46] = s28;
        values[47] = s33;
        values[48] = s35;
        values[49] = s28;
        values[50] = s33;
        values[51] = s35;
        values[52] = s32;
        values[53] = s37;
        values[54] = s39;
        values[55] = s32;
        values[56] = s37;
        values[57] = s39;
        values[58] = s36;
        values[59] = s41;
        values[60] = s43;
        values[61] = s36;
        values[62] = s41;
        values[63] = s43;
        values[64] = s40;
        values[65] = s45;
        values[66] = s47;
        values[67] = s40;
        values[68] = s45;
        values[69] = s47;
        values[70] = s44;
        values[71] = s49;
        values[72] = s51;
        values[73] = s44;
        values[74] = s49;
        values[75] = s51;
        values[76] = s48;
        values[77] = s53;
        values[78] = s55;
        values[79] = s48;
        values[80] = s53;
        values[81] = s55;
        values[82] = s52;
        values[83] = s57;
        values[84] = s59;
        values[85] = s52;
        values[86] = s57;
        values[87] = s59;
        values[88] = s56;
        values[89] = s61;
        values[90] = s63;
        values[91] = s56;
        values[92] = s61;
        values[93] = s63;
        values[94] = s60;
        values[95] = s65;
        values[96] = s67;
        values[97] = s60;
        values[98] = s65;
        values[99] = s67;
        values[100] = s64;
        values[101] = s69;
        values[102] = s71;
        values[103] = s64;
        values[104] = s69;
        values[105] = s71;
        values[106] = s68;
        values[107] = s73;
        values[108] = s75;
        values[109] = s68;
        values[110] = s73;
        values[111] = s75;
        values[112] = s72;
        values[113] = s77;
        values[114] = s79;
        values[115] = s72;
        values[116] = s77;
        values[117] = s79;
        values[118] = s76;
        values[119] = s81;
        values[120] = s83;
        values[121] = s76;
        values[122] = s81;
        values[123] = s83;
        values[124] = s80;
        values[125] = s85;
        values[126] = s87;
        values[127] = s80;
        values[128] = s85;
        values[129] = s87;
        values[130] = s84;
        values[131] = s89;
        values[132] = s91;
        values[133] = s84;
        values[134] = s89;
        values[135] = s91;
        values[136] = s88;
        values[137] = s93;
        values[138] = s95;
        values[139] = s88;
        values[140] = s93;
        values[141] = s95;
        values[142] = s92;
        values[143] = s97;
        values[144] = s99;
        values[145] = s92;
        values[146] = s97;
        values[147] = s99;
        values[148] = s96;
        values[149] = s101;
        values[150] = s103;
        values[151] = s96;
        values[152] = s101;
        values[153] = s103;
        values[154] = s100;
        values[155] = s105;
        values[156] = s107;
        values[157] = s100;
        values[158] = s105;
        values[159] = s107;
        values[160] = s104;
        values[161] = s109;
        values[162] = s111;
        values[163] = s104;
        values[164] = s109;
        values[165] = s111;
        values[166] = s108;
        values[167] = s113;
        values[168] = s115;
        values[169] = s108;
        values[170] = s113;
        values[171] = s115;
        values[172] = s112;
        values[173] = s117;
        values[174] = s119;
        values[175] = s112;
        values[176] = s117;
        values[177] = s119;
        values[178] = s116;
        values[179] = s121;
        values[180] = s123;
        values[181] = s116;
        values[182] = s121;
        values[183] = s123;
        values[184] = s120;
        values[185] = s125;
        values[186] = s127;
        values[187] = s120;
        values[188] = s125;
        values[189] = s127;
        values[190] = s124;
        values[191] = s129;
        values[192] = s131;
        values[193] = s124;
        values[194] = s129;
        values[195] = s131;
        values[196] = s128;
        values[197] = s133;
        values[198] = s135;
        values[199] = s128;
        values[200] = s133;
        values[201] = s135;
        values[202] = s132;
        values[203] = s137;
        values[204] = s139;
        values[205] = s132;
        values[206] = s137;
        values[207] = s139;
        values[208] = s136;
        values[209] = s141;
        values[210] = s143;
        values[211] = s136;
        values[212] = s141;
        values[213] = s143;
        values[214] = s140;
        values[215] = s145;
        values[216] = s147;
        values[217] = s140;
        values[218] = s145;
        values[219] = s147;
        values[220] = s144;
        values[221] = s149;
        values[222] = s151;
        values[223] = s144;
        values[224] = s149;
        values[225] = s151;
        values[226] = s148;
        values[227] = s153;
        values[228] = s155;
        values[229] = s148;
        values[230] = s153;
        values[231] = s155;
        values[232] = s152;
        values[233] = s157;
        values[234] = s159;
        values[235] = s152;
        values[236] = s157;
        values[237] = s159;
        values[238] = s156;
        values[239] = s161;
        values[240] = s163;
        values[241] = s156;
        values[242] = s161;
        values[243] = s163;
        values[244] = s160;
        values[245] = s165;
        values[246] = s167;
        values[247] = s160;
        values[248] = s165;
        values[249] = s167;
        values[250] = s164;
        values[251] = s169;
        values[252] = s171;
        values[253] = s164;
        values[254] = s169;
        values[255] = s171;
        values[256] = s168;
        values[257] = s173;
        values[258] = s175;
        values[259] = s168;
        values[260] = s173;
        values[261] = s175;
        values[262] = s172;
        values[263] = s177;
        values[264] = s179;
        values[265] = s172;
        values[266] = s177;
        values[267] = s179;
        values[268] = s176;
        values[269] = s181;
        values[270] = s183;
        values[271] = s176;
        values[272] = s181;
        values[273] = s183;
        values[274] = s180;
        values[275] = s185;
        values[276] = s187;
        values[277] = s180;
        values[278] = s185;
        values[279] = s187;
        values[280] = s184;
        values[281] = s189;
        values[282] = s191;
        values[283] = s184;
        values[284] = s189;
        values[285] = s191;
        values[286] = s188;
        values[287] = s193;
        values[288] = s195;
        values[289] = s188;
        values[290] = s193;
        values[291] = s195;
        values[292] = s192;
        values[293] = s197;
        values[294] = s199;
        values[295] = s192;
        values[296] = s197;
        values[297] = s199;
        values[298] = s196;
        values[299] = s201;
        values[300] = s203;
        values[301] = s196;
        values[302] = s201;
        values[303] = s203;
        values[304] = s200;
        values[305] = s205;
        values[306] = s207;
        values[307] = s200;
        values[308] = s205;
        values[309] = s207;
        values[310] = s204;
        values[311] = s209;
        values[312] = s211;
        values[313] = s204;
        values[314] = s209;
        values[315] = s211;
        values[316] = s208;
        values[317] = s213;
        values[318] = s215;
        values[319] = s208;
        values[320] = s213;
        values[321] = s215;
        values[322] = s212;
        values[323] = s217;
        values[324] = s219;
        values[325] = s212;
        values[326] = s217;
        values[327] = s219;
        values[328] = s216;
        values[329] = s221;
        values[330] = s223;
        values[331] = s216;
        values[332] = s221;
        values[333] = s223;
        values[334] = s220;
        values[335] = s225;
        values[336] = s227;
        values[337] = s220;
        values[338] = s225;
        values[339] = s227;
        values[340] = s224;
        values[341] = s229;
        values[342] = s231;
        values[343] = s224;
        values[344] = s229;
        values[345] = s231;
        values[346] = s228;
        values[347] = s233;
        values[348] = s235;
        values[349] = s228;
        values[350] = s233;
        values[351] = s235;
        values[352] = s232;
        values[353] = s237;
        values[354] = s239;
        values[355] = s232;
        values[356] = s237;
        values[357] = s239;
        values[358] = s236;
        values[359] = s241;
        values[360] = s243;
        values[361] = s236;
        values[362] = s241;
        values[363] = s243;
        values[364] = s240;
        values[365] = s245;
        values[366] = s247;
        values[367] = s240;
        values[368] = s245;
        values[369] = s247;
        values[370] = s244;
        values[371] = s249;
        values[372] = s251;
        values[373] = s244;
        values[374] = s249;
        values[375] = s251;
        values[376] = s248;
        values[377] = s253;
        values[378] = s255;
        values[379] = s248;
        values[380] = s253;
        values[381] = s255;
        values[382] = s252;
        values[383] = s257;
        values[384] = s259;
        values[385] = s252;
        values[386] = s257;
        values[387] = s259;
        values[388] = s256;
        values[389] = s261;
        values[390] = s263;
        values[391] = s256;
        values[392] = s261;
        values[393] = s263;
        values[394] = s260;
        values[395] = s265;
        values[396] = s267;
        values[397] = s260;
        values[398] = s265;
        values[399] = s267;
        values[400] = s264;
        values[401] = s269;
        values[402] = s271;
        values[403] = s264;
        values[404] = s269;
        values[405] = s271;
        values[406] = s268;
        values[407] = s273;
        values[408] = s275;
        values[409] = s268;
        values[410] = s273;
        values[411] = s275;
        values[412] = s272;
        values[413] = s277;
        values[414] = s279;
        values[415] = s272;
        values[416] = s277;
        values[417] = s279;
        values[418] = s276;
        values[419] = s281;
        values[420] = s283;
        values[421] = s276;
        values[422] = s281;
        values[423] = s283;
        values[424] = s280;
        values[425] = s285;
        values[426] = s287;
        values[427] = s280;
        values[428] = s285;
        values[429] = s287;
        values[430] = s284;
        values[431] = s289;
        values[432] = s291;
        values[433] = s284;
        values[434] = s289;
        values[435] = s291;
        values[436] = s288;
        values[437] = s293;
        values[438] = s295;
        values[439] = s288;
        values[440] = s293;
        values[441] = s295;
        values[442] = s292;
        values[443] = s297;
        values[444] = s299;
        values[445] = s292;
        values[446] = s297;
        values[447] = s299;
        values[448] = s296;
        values[449] = s301;
        values[450] = s303;
        values[451] = s296;
        values[452] = s301;
        values[453] = s303;
        values[454] = s300;
        values[455] = s305;
        values[456] = s307;
        values[457] = s300;
        values[458] = s305;
        values[459] = s307;
        values[460] = s304;
        values[461] = s309;
        values[462] = s311;
        values[463] = s304;
        values[464] = s309;
        values[465] = s311;
        values[466] = s308;
        values[467] = s313;
        values[468] = s315;
        values[469] = s308;
        values[470] = s313;
        values[471] = s315;
        values[472] = s312;
        values[473] = s317;
        values[474] = s319;
        values[475] = s312;
        values[476] = s317;
        values[477] = s319;
        values[478] = s316;
        values[479] = s321;
        values[480] = s323;
        values[481] = s316;
        values[482] = s321;
        values[483] = s323;
        values[484] = s320;
        values[485] = s325;
        values[486] = s327;
        values[487] = s320;
        values[488] = s325;
        values[489] = s327;
        values[490] = s324;
        values[491] = s329;
        values[492] = s331;
        values[493] = s324;
        values[494] = s329;
        values[495] = s331;
        values[496] = s328;
        values[497] = s333;
        values[498] = s335;
        values[499] = s328;
        values[500] = s333;
        values[501] = s335;
        values[502] = s332;
        values[503] = s337;
        values[504] = s339;
        values[505] = s332;
        values[506] = s337;
        values[507] = s339;
        values[508] = s336;
        values[509] = s341;
        values[510] = s343;
        values[511] = s336;
        values[512] = s341;
        values[513] = s343;
        values[514] = s340;
        values[515] = s345;
        values[516] = s347;
        values[517] = s340;
        values[518] = s345;
        values[519] = s347;
        values[520] = s344;
        values[521] = s349;
        values[522] = s351;
        values[523] = s344;
        values[524] = s349;
        values[525] = s351;
        values[526] = s348;
        values[527] = s353;
        values[528] = s355;
        values[529] = s348;
        values[530] = s353;
        values[531] = s355;
        values[532] = s352;
        values[533] = s357;
        values[534] = s359;
        values[535] = s352;
        values[536] = s357;
        values[537] = s359;
        values[538] = s356;
        values[539] = s361;
        values[540] = s363;
        values[541] = s356;
        values[542] = s361;
        values[543] = s363;
        values[544] = s360;
        values[545] = s365;
        values[546] = s367;
        values[547] = s360;
        values[548] = s365;
        values[549] = s367;
        values[550] = s364;
        values[551] = s369;
        values[552] = s371;
        values[553] = s364;
        values[554] = s369;
        values[555] = s371;
        values[556] = s368;
        values[557] = s373;
        values[558] = s375;
        values[559] = s368;
        values[560] = s373;
        values[561] = s375;
        values[562] = s372;
        values[563] = s377;
        values[564] = s379;
        values[565] = s372;
        values[566] = s377;
        values[567] = s379;
        values[568] = s376;
        values[569] = s381;
        values[570] = s383;
        values[571] = s376;
        values[572] = s381;
        values[573] = s383;
        values[574] = s380;
        values[575] = s385;
        values[576] = s387;
        values[577] = s380;
        values[578] = s385;
        values[579] = s387;
        values[580] = s384;
        values[581] = s389;
        values[582] = s391;
        values[583] = s384;
        values[584] = s389;
        values[585] = s391;
        values[586] = s388;
        values[587] = s393;
        values[588] = s395;
        values[589] = s388;
        values[590] = s393;
        values[591] = s395;
        values[592] = s392;
        values[593] = s394;
        values[594] = s392;
        values[595] = s394;
    }
}
