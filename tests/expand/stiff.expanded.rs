#[allow(dead_code)]
impl SpringPendulum {
    fn mass(&self) -> [Float; 4] {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        [self.m1, self.m1, self.m2, self.m2]
    }
    fn force(
        &self,
        [x1,
        y1,
        x2,
        y2,
        ]: [Float; 4],
        [u1,
        w1,
        u2,
        w2,
        ]: [Float; 4],
    ) -> [Float; 4] {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let fx = self.k * (x2 - x1) + self.c * (u2 - u1);
        let fy = self.k * (y2 - y1 + self.l0) + self.c * (w2 - w1);
        [fx, fy - self.m1 * self.g, -fx, -fy - self.m2 * self.g]
    }
    fn constraints(&self, [x1, y1, _x2, _y2]: [Float; 4]) -> [Float; 1] {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        [x1 * x1 + y1 * y1 - self.l * self.l]
    }
}
#[allow(unused_variables, unused_mut, clippy::all)]
impl ::zeitner::__private::ConstrainedSystem<4, 1> for SpringPendulum {
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
                        nonzeros: &[(0, 0), (1, 0), (2, 0), (3, 0)],
                    },
                ],
                ops: ::zeitner::__private::OpCounts {
                    adds: 11u64,
                    muls: 6u64,
                    divs: 0u64,
                    transcendental: 0u64,
                    opaque_calls: 0u64,
                },
                ops_unshared: ::zeitner::__private::OpCounts {
                    adds: 18u64,
                    muls: 10u64,
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
                    adds: 2u64,
                    muls: 3u64,
                    divs: 0u64,
                    transcendental: 0u64,
                    opaque_calls: 0u64,
                },
                ops_unshared: ::zeitner::__private::OpCounts {
                    adds: 2u64,
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
                        nonzeros: &[(0, 0), (0, 1)],
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
                        rows: 1,
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
                        rows: 1,
                        cols: 4,
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
                    adds: 12u64,
                    muls: 12u64,
                    divs: 0u64,
                    transcendental: 0u64,
                    opaque_calls: 0u64,
                },
                ops_unshared: ::zeitner::__private::OpCounts {
                    adds: 19u64,
                    muls: 16u64,
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
                ],
                ops: ::zeitner::__private::OpCounts {
                    adds: 2u64,
                    muls: 0u64,
                    divs: 0u64,
                    transcendental: 0u64,
                    opaque_calls: 0u64,
                },
                ops_unshared: ::zeitner::__private::OpCounts {
                    adds: 8u64,
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
                        nonzeros: &[(0, 0), (1, 1)],
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
        ],
    };
    type Mass = ::zeitner::__private::DiagonalMass<4>;
    type Storage = ::zeitner::__private::Dense;
    const SPARSITY: ::core::option::Option<::zeitner::__private::Sparsity> = ::core::option::Option::Some(::zeitner::__private::Sparsity {
        constraint_jacobian: &[(0, 0), (0, 1)],
        force_jacobians: [
            &[(0, 0), (0, 2), (1, 1), (1, 3), (2, 0), (2, 2), (3, 1), (3, 3)],
            &[(0, 0), (0, 2), (1, 1), (1, 3), (2, 0), (2, 2), (3, 1), (3, 3)],
        ],
        constraint_force_jacobians: [&[(0, 0), (1, 1)], &[]],
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
        m[0] = self.m1;
        m[1] = self.m1;
        m[2] = self.m2;
        m[3] = self.m2;
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
        let s0 = self.k * (q[2] - q[0]) + self.c * (v[2] - v[0]);
        let s1 = self.k * (q[3] - q[1] + self.l0) + self.c * (v[3] - v[1]);
        let mut f = ::zeitner::__private::Vector::<4>::zeros();
        f[0] = s0;
        f[1] = s1 - self.m1 * self.g;
        f[2] = -s0;
        f[3] = -s1 - self.m2 * self.g;
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
        g[0] = q[0].powi(2) + q[1].powi(2) - self.l.powi(2);
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
        let mut g = ::zeitner::__private::Matrix::<1, 4>::zeros();
        g[(0, 0)] = 2.0 * q[0];
        g[(0, 1)] = 2.0 * q[1];
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
        let mut w = ::zeitner::__private::Vector::<1>::zeros();
        w[0] = v[0] * (2.0 * q[0]) + v[1] * (2.0 * q[1]);
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
        b[0] = v[0] * (2.0 * v[0]) + v[1] * (2.0 * v[1]);
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
        let s0 = self.k * (q[2] - q[0]) + self.c * (v[2] - v[0]);
        let s1 = self.k * (q[3] - q[1] + self.l0) + self.c * (v[3] - v[1]);
        let mut m = ::zeitner::__private::Vector::<4>::zeros();
        let mut f = ::zeitner::__private::Vector::<4>::zeros();
        let mut g = ::zeitner::__private::Matrix::<1, 4>::zeros();
        let mut b = ::zeitner::__private::Vector::<1>::zeros();
        m[0] = self.m1;
        m[1] = self.m1;
        m[2] = self.m2;
        m[3] = self.m2;
        f[0] = s0;
        f[1] = s1 - self.m1 * self.g;
        f[2] = -s0;
        f[3] = -s1 - self.m2 * self.g;
        g[(0, 0)] = 2.0 * q[0];
        g[(0, 1)] = 2.0 * q[1];
        b[0] = v[0] * (2.0 * v[0]) + v[1] * (2.0 * v[1]);
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
        dq[(0, 2)] = self.k;
        dq[(1, 1)] = s0;
        dq[(1, 3)] = self.k;
        dq[(2, 0)] = self.k;
        dq[(2, 2)] = s0;
        dq[(3, 1)] = self.k;
        dq[(3, 3)] = s0;
        dv[(0, 0)] = s1;
        dv[(0, 2)] = self.c;
        dv[(1, 1)] = s1;
        dv[(1, 3)] = self.c;
        dv[(2, 0)] = self.c;
        dv[(2, 2)] = s1;
        dv[(3, 1)] = self.c;
        dv[(3, 3)] = s1;
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
        let s0 = 2.0 * lambda[0];
        let mut dq = ::zeitner::__private::Matrix::<4, 4>::zeros();
        let mut dv = ::zeitner::__private::Matrix::<4, 4>::zeros();
        dq[(0, 0)] = s0;
        dq[(1, 1)] = s0;
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
        values[0] = 2.0 * q[0];
        values[1] = 2.0 * q[1];
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
        values[1] = self.k;
        values[2] = s0;
        values[3] = self.k;
        values[4] = self.k;
        values[5] = s0;
        values[6] = self.k;
        values[7] = s0;
        values[8] = s1;
        values[9] = self.c;
        values[10] = s1;
        values[11] = self.c;
        values[12] = self.c;
        values[13] = s1;
        values[14] = self.c;
        values[15] = s1;
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
        let s0 = 2.0 * lambda[0];
        values[0] = s0;
        values[1] = s0;
    }
}
#[allow(dead_code)]
impl DoublePendulum {
    fn mass(&self) -> [Float; 4] {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        [self.m1, self.m1, self.m2, self.m2]
    }
    fn force(&self) -> [Float; 4] {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        [0.0, -self.m1 * self.g, 0.0, -self.m2 * self.g]
    }
    fn constraints(&self, [x1, y1, x2, y2]: [Float; 4]) -> [Float; 2] {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        [
            x1 * x1 + y1 * y1 - self.l1 * self.l1,
            (x2 - x1).powi(2) + (y2 - y1).powi(2) - self.l2 * self.l2,
        ]
    }
}
#[allow(unused_variables, unused_mut, clippy::all)]
impl ::zeitner::__private::ConstrainedSystem<4, 2> for DoublePendulum {
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
        m[0] = self.m1;
        m[1] = self.m1;
        m[2] = self.m2;
        m[3] = self.m2;
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
        f[1] = -(self.m1 * self.g);
        f[3] = -(self.m2 * self.g);
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
        let mut g = ::zeitner::__private::Vector::<2>::zeros();
        g[0] = q[0].powi(2) + q[1].powi(2) - self.l1.powi(2);
        g[1] = (q[2] - q[0]).powi(2) + (q[3] - q[1]).powi(2) - self.l2.powi(2);
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
        let s0 = 2.0 * (q[2] - q[0]);
        let s1 = 2.0 * (q[3] - q[1]);
        let s2 = 2.0 * v[0];
        let s3 = 2.0 * v[1];
        let mut m = ::zeitner::__private::Vector::<4>::zeros();
        let mut f = ::zeitner::__private::Vector::<4>::zeros();
        let mut g = ::zeitner::__private::Matrix::<2, 4>::zeros();
        let mut b = ::zeitner::__private::Vector::<2>::zeros();
        m[0] = self.m1;
        m[1] = self.m1;
        m[2] = self.m2;
        m[3] = self.m2;
        f[1] = -(self.m1 * self.g);
        f[3] = -(self.m2 * self.g);
        g[(0, 0)] = 2.0 * q[0];
        g[(0, 1)] = 2.0 * q[1];
        g[(1, 0)] = -s0;
        g[(1, 1)] = -s1;
        g[(1, 2)] = s0;
        g[(1, 3)] = s1;
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
impl SliderCrank {
    fn mass(&self) -> [Float; 3] {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        [self.m, self.m, self.ms]
    }
    fn force(&self) -> [Float; 3] {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        [0.0, 0.0, 0.0]
    }
    fn constraints(&self, [xa, ya, xs]: [Float; 3]) -> [Float; 2] {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        [
            xa * xa + ya * ya - self.r * self.r,
            (xs - xa).powi(2) + ya * ya - self.l * self.l,
        ]
    }
}
#[allow(unused_variables, unused_mut, clippy::all)]
impl ::zeitner::__private::ConstrainedSystem<3, 2> for SliderCrank {
    const POSITION_CONSTRAINTS: usize = 2;
    const MASS_IS_CONSTANT: bool = true;
    const DYNAMICS_DEPEND_ON_VELOCITY: bool = false;
    const SUMMARY: ::zeitner::__private::SceneSummary = ::zeitner::__private::SceneSummary {
        coordinates: 3,
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
                    muls: 5u64,
                    divs: 0u64,
                    transcendental: 0u64,
                    opaque_calls: 0u64,
                },
                ops_unshared: ::zeitner::__private::OpCounts {
                    adds: 5u64,
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
                        cols: 3,
                        nonzeros: &[(0, 0), (0, 1), (1, 0), (1, 1), (1, 2)],
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
                    adds: 3u64,
                    muls: 5u64,
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
                    muls: 7u64,
                    divs: 0u64,
                    transcendental: 0u64,
                    opaque_calls: 0u64,
                },
                ops_unshared: ::zeitner::__private::OpCounts {
                    adds: 5u64,
                    muls: 10u64,
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
                    adds: 5u64,
                    muls: 9u64,
                    divs: 0u64,
                    transcendental: 0u64,
                    opaque_calls: 0u64,
                },
                ops_unshared: ::zeitner::__private::OpCounts {
                    adds: 5u64,
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
                        rows: 3,
                        cols: 1,
                        nonzeros: &[(0, 0), (1, 0), (2, 0)],
                    },
                    ::zeitner::__private::BlockSummary {
                        name: "f",
                        rows: 3,
                        cols: 1,
                        nonzeros: &[],
                    },
                    ::zeitner::__private::BlockSummary {
                        name: "g",
                        rows: 2,
                        cols: 3,
                        nonzeros: &[(0, 0), (0, 1), (1, 0), (1, 1), (1, 2)],
                    },
                    ::zeitner::__private::BlockSummary {
                        name: "b",
                        rows: 2,
                        cols: 1,
                        nonzeros: &[(0, 0), (1, 0)],
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
                    adds: 8u64,
                    muls: 17u64,
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
                        nonzeros: &[(0, 0), (0, 2), (1, 1), (2, 0), (2, 2)],
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
                    muls: 3u64,
                    divs: 0u64,
                    transcendental: 0u64,
                    opaque_calls: 0u64,
                },
                ops_unshared: ::zeitner::__private::OpCounts {
                    adds: 3u64,
                    muls: 7u64,
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
        constraint_jacobian: &[(0, 0), (0, 1), (1, 0), (1, 1), (1, 2)],
        force_jacobians: [&[], &[]],
        constraint_force_jacobians: [&[(0, 0), (0, 2), (1, 1), (2, 0), (2, 2)], &[]],
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
        m[2] = self.ms;
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
        let s0 = q[1].powi(2);
        let mut g = ::zeitner::__private::Vector::<2>::zeros();
        g[0] = q[0].powi(2) + s0 - self.r.powi(2);
        g[1] = s0 + (q[2] - q[0]).powi(2) - self.l.powi(2);
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
        let s0 = 2.0 * q[1];
        let s1 = 2.0 * (q[2] - q[0]);
        let mut g = ::zeitner::__private::Matrix::<2, 3>::zeros();
        g[(0, 0)] = 2.0 * q[0];
        g[(0, 1)] = s0;
        g[(1, 0)] = -s1;
        g[(1, 1)] = s0;
        g[(1, 2)] = s1;
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
        let s0 = 2.0 * (q[2] - q[0]);
        let s1 = 2.0 * q[1] * v[1];
        let mut w = ::zeitner::__private::Vector::<2>::zeros();
        w[0] = 2.0 * q[0] * v[0] + s1;
        w[1] = s1 - s0 * v[0] + s0 * v[2];
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
        let s0 = 2.0 * v[0];
        let s1 = v[1] * (2.0 * v[1]);
        let mut b = ::zeitner::__private::Vector::<2>::zeros();
        b[0] = v[0] * s0 + s1;
        b[1] = s1 + v[0] * (-2.0 * v[2] - -2.0 * v[0]) + v[2] * (2.0 * v[2] - s0);
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
        let s0 = 2.0 * q[1];
        let s1 = 2.0 * (q[2] - q[0]);
        let s2 = 2.0 * v[0];
        let s3 = v[1] * (2.0 * v[1]);
        let mut m = ::zeitner::__private::Vector::<3>::zeros();
        let mut f = ::zeitner::__private::Vector::<3>::zeros();
        let mut g = ::zeitner::__private::Matrix::<2, 3>::zeros();
        let mut b = ::zeitner::__private::Vector::<2>::zeros();
        m[0] = self.m;
        m[1] = self.m;
        m[2] = self.ms;
        g[(0, 0)] = 2.0 * q[0];
        g[(0, 1)] = s0;
        g[(1, 0)] = -s1;
        g[(1, 1)] = s0;
        g[(1, 2)] = s1;
        b[0] = v[0] * s2 + s3;
        b[1] = s3 + v[0] * (-2.0 * v[2] - -2.0 * v[0]) + v[2] * (2.0 * v[2] - s2);
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
        let s0 = 2.0 * lambda[0];
        let s1 = -2.0 * lambda[1];
        let s2 = 2.0 * lambda[1];
        let mut dq = ::zeitner::__private::Matrix::<3, 3>::zeros();
        let mut dv = ::zeitner::__private::Matrix::<3, 3>::zeros();
        dq[(0, 0)] = s0 - s1;
        dq[(0, 2)] = -s2;
        dq[(1, 1)] = s0 + s2;
        dq[(2, 0)] = s1;
        dq[(2, 2)] = s2;
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
        let s0 = 2.0 * q[1];
        let s1 = 2.0 * (q[2] - q[0]);
        values[0] = 2.0 * q[0];
        values[1] = s0;
        values[2] = -s1;
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
        lambda: &::zeitner::__private::Vector<2>,
        values: &mut [::zeitner::__private::Float],
    ) {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let s0 = 2.0 * lambda[0];
        let s1 = -2.0 * lambda[1];
        let s2 = 2.0 * lambda[1];
        values[0] = s0 - s1;
        values[1] = -s2;
        values[2] = s0 + s2;
        values[3] = s1;
        values[4] = s2;
    }
}
#[allow(dead_code)]
impl RedundantFourBar {
    fn mass(&self) -> [Float; 4] {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        [self.m, self.m, self.m, self.m]
    }
    fn force(&self) -> [Float; 4] {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        [0.0, -self.m * self.g, 0.0, -self.m * self.g]
    }
    fn constraints(&self, [xa, ya, xb, yb]: [Float; 4]) -> [Float; 4] {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let crank = xa * xa + ya * ya - self.r1 * self.r1;
        let rocker = (xb - self.d).powi(2) + yb * yb - self.r3 * self.r3;
        [
            crank,
            (xb - xa).powi(2) + (yb - ya).powi(2) - self.r2 * self.r2,
            rocker,
            crank + rocker,
        ]
    }
}
#[allow(unused_variables, unused_mut, clippy::all)]
impl ::zeitner::__private::ConstrainedSystem<4, 4> for RedundantFourBar {
    const POSITION_CONSTRAINTS: usize = 4;
    const MASS_IS_CONSTANT: bool = true;
    const DYNAMICS_DEPEND_ON_VELOCITY: bool = false;
    const SUMMARY: ::zeitner::__private::SceneSummary = ::zeitner::__private::SceneSummary {
        coordinates: 4,
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
                        rows: 4,
                        cols: 1,
                        nonzeros: &[(0, 0), (1, 0), (2, 0), (3, 0)],
                    },
                ],
                ops: ::zeitner::__private::OpCounts {
                    adds: 10u64,
                    muls: 9u64,
                    divs: 0u64,
                    transcendental: 0u64,
                    opaque_calls: 0u64,
                },
                ops_unshared: ::zeitner::__private::OpCounts {
                    adds: 15u64,
                    muls: 15u64,
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
                        nonzeros: &[
                            (0, 0),
                            (0, 1),
                            (1, 0),
                            (1, 1),
                            (1, 2),
                            (1, 3),
                            (2, 2),
                            (2, 3),
                            (3, 0),
                            (3, 1),
                            (3, 2),
                            (3, 3),
                        ],
                    },
                ],
                ops: ::zeitner::__private::OpCounts {
                    adds: 5u64,
                    muls: 6u64,
                    divs: 0u64,
                    transcendental: 0u64,
                    opaque_calls: 0u64,
                },
                ops_unshared: ::zeitner::__private::OpCounts {
                    adds: 8u64,
                    muls: 12u64,
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
                    adds: 11u64,
                    muls: 14u64,
                    divs: 0u64,
                    transcendental: 0u64,
                    opaque_calls: 0u64,
                },
                ops_unshared: ::zeitner::__private::OpCounts {
                    adds: 15u64,
                    muls: 24u64,
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
                    adds: 11u64,
                    muls: 16u64,
                    divs: 0u64,
                    transcendental: 0u64,
                    opaque_calls: 0u64,
                },
                ops_unshared: ::zeitner::__private::OpCounts {
                    adds: 12u64,
                    muls: 28u64,
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
                        rows: 4,
                        cols: 4,
                        nonzeros: &[
                            (0, 0),
                            (0, 1),
                            (1, 0),
                            (1, 1),
                            (1, 2),
                            (1, 3),
                            (2, 2),
                            (2, 3),
                            (3, 0),
                            (3, 1),
                            (3, 2),
                            (3, 3),
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
                    adds: 17u64,
                    muls: 23u64,
                    divs: 0u64,
                    transcendental: 0u64,
                    opaque_calls: 0u64,
                },
                ops_unshared: ::zeitner::__private::OpCounts {
                    adds: 22u64,
                    muls: 42u64,
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
                    adds: 5u64,
                    muls: 5u64,
                    divs: 0u64,
                    transcendental: 0u64,
                    opaque_calls: 0u64,
                },
                ops_unshared: ::zeitner::__private::OpCounts {
                    adds: 10u64,
                    muls: 16u64,
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
        constraint_jacobian: &[
            (0, 0),
            (0, 1),
            (1, 0),
            (1, 1),
            (1, 2),
            (1, 3),
            (2, 2),
            (2, 3),
            (3, 0),
            (3, 1),
            (3, 2),
            (3, 3),
        ],
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
    ) -> ::zeitner::__private::Vector<4> {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let s0 = q[0].powi(2) + q[1].powi(2) - self.r1.powi(2);
        let s1 = (q[2] - self.d).powi(2) + q[3].powi(2) - self.r3.powi(2);
        let mut g = ::zeitner::__private::Vector::<4>::zeros();
        g[0] = s0;
        g[1] = (q[2] - q[0]).powi(2) + (q[3] - q[1]).powi(2) - self.r2.powi(2);
        g[2] = s1;
        g[3] = s0 + s1;
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
        let s0 = 2.0 * q[0];
        let s1 = 2.0 * q[1];
        let s2 = 2.0 * (q[2] - q[0]);
        let s3 = 2.0 * (q[3] - q[1]);
        let s4 = 2.0 * (q[2] - self.d);
        let s5 = 2.0 * q[3];
        let mut g = ::zeitner::__private::Matrix::<4, 4>::zeros();
        g[(0, 0)] = s0;
        g[(0, 1)] = s1;
        g[(1, 0)] = -s2;
        g[(1, 1)] = -s3;
        g[(1, 2)] = s2;
        g[(1, 3)] = s3;
        g[(2, 2)] = s4;
        g[(2, 3)] = s5;
        g[(3, 0)] = s0;
        g[(3, 1)] = s1;
        g[(3, 2)] = s4;
        g[(3, 3)] = s5;
        g
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
        let s0 = 2.0 * (q[2] - q[0]);
        let s1 = 2.0 * (q[3] - q[1]);
        let s2 = 2.0 * q[0] * v[0] + 2.0 * q[1] * v[1];
        let s3 = 2.0 * (q[2] - self.d) * v[2];
        let s4 = 2.0 * q[3] * v[3];
        let mut w = ::zeitner::__private::Vector::<4>::zeros();
        w[0] = s2;
        w[1] = -(s0 * v[0]) - s1 * v[1] + s0 * v[2] + s1 * v[3];
        w[2] = s3 + s4;
        w[3] = s4 + s2 + s3;
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
        let s0 = 2.0 * v[0];
        let s1 = 2.0 * v[1];
        let s2 = v[0] * s0 + v[1] * s1;
        let s3 = 2.0 * v[2];
        let s4 = 2.0 * v[3];
        let s5 = v[2] * s3;
        let s6 = v[3] * s4;
        let mut b = ::zeitner::__private::Vector::<4>::zeros();
        b[0] = s2;
        b[1] = v[0] * (-2.0 * v[2] - -2.0 * v[0]) + v[1] * (-2.0 * v[3] - -2.0 * v[1])
            + v[2] * (s3 - s0) + v[3] * (s4 - s1);
        b[2] = s5 + s6;
        b[3] = s6 + s2 + s5;
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
        let s0 = -(self.m * self.g);
        let s1 = 2.0 * q[0];
        let s2 = 2.0 * q[1];
        let s3 = 2.0 * (q[2] - q[0]);
        let s4 = 2.0 * (q[3] - q[1]);
        let s5 = 2.0 * (q[2] - self.d);
        let s6 = 2.0 * q[3];
        let s7 = 2.0 * v[0];
        let s8 = 2.0 * v[1];
        let s9 = v[0] * s7 + v[1] * s8;
        let s10 = 2.0 * v[2];
        let s11 = 2.0 * v[3];
        let s12 = v[2] * s10;
        let s13 = v[3] * s11;
        let mut m = ::zeitner::__private::Vector::<4>::zeros();
        let mut f = ::zeitner::__private::Vector::<4>::zeros();
        let mut g = ::zeitner::__private::Matrix::<4, 4>::zeros();
        let mut b = ::zeitner::__private::Vector::<4>::zeros();
        m[0] = self.m;
        m[1] = self.m;
        m[2] = self.m;
        m[3] = self.m;
        f[1] = s0;
        f[3] = s0;
        g[(0, 0)] = s1;
        g[(0, 1)] = s2;
        g[(1, 0)] = -s3;
        g[(1, 1)] = -s4;
        g[(1, 2)] = s3;
        g[(1, 3)] = s4;
        g[(2, 2)] = s5;
        g[(2, 3)] = s6;
        g[(3, 0)] = s1;
        g[(3, 1)] = s2;
        g[(3, 2)] = s5;
        g[(3, 3)] = s6;
        b[0] = s9;
        b[1] = v[0] * (-2.0 * v[2] - -2.0 * v[0]) + v[1] * (-2.0 * v[3] - -2.0 * v[1])
            + v[2] * (s10 - s7) + v[3] * (s11 - s8);
        b[2] = s12 + s13;
        b[3] = s13 + s9 + s12;
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
        lambda: &::zeitner::__private::Vector<4>,
    ) -> (::zeitner::__private::Matrix<4, 4>, ::zeitner::__private::Matrix<4, 4>) {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let s0 = -2.0 * lambda[1];
        let s1 = 2.0 * lambda[3];
        let s2 = 2.0 * lambda[0] - s0 + s1;
        let s3 = 2.0 * lambda[1];
        let s4 = -s3;
        let s5 = s1 + s3 + 2.0 * lambda[2];
        let mut dq = ::zeitner::__private::Matrix::<4, 4>::zeros();
        let mut dv = ::zeitner::__private::Matrix::<4, 4>::zeros();
        dq[(0, 0)] = s2;
        dq[(0, 2)] = s4;
        dq[(1, 1)] = s2;
        dq[(1, 3)] = s4;
        dq[(2, 0)] = s0;
        dq[(2, 2)] = s5;
        dq[(3, 1)] = s0;
        dq[(3, 3)] = s5;
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
        let s0 = 2.0 * q[0];
        let s1 = 2.0 * q[1];
        let s2 = 2.0 * (q[2] - q[0]);
        let s3 = 2.0 * (q[3] - q[1]);
        let s4 = 2.0 * (q[2] - self.d);
        let s5 = 2.0 * q[3];
        values[0] = s0;
        values[1] = s1;
        values[2] = -s2;
        values[3] = -s3;
        values[4] = s2;
        values[5] = s3;
        values[6] = s4;
        values[7] = s5;
        values[8] = s0;
        values[9] = s1;
        values[10] = s4;
        values[11] = s5;
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
        lambda: &::zeitner::__private::Vector<4>,
        values: &mut [::zeitner::__private::Float],
    ) {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let s0 = -2.0 * lambda[1];
        let s1 = 2.0 * lambda[3];
        let s2 = 2.0 * lambda[0] - s0 + s1;
        let s3 = 2.0 * lambda[1];
        let s4 = -s3;
        let s5 = s1 + s3 + 2.0 * lambda[2];
        values[0] = s2;
        values[1] = s4;
        values[2] = s2;
        values[3] = s4;
        values[4] = s0;
        values[5] = s5;
        values[6] = s0;
        values[7] = s5;
    }
}
#[allow(dead_code)]
impl CoupledMassPendulum {
    fn mass(&self) -> [[Float; 2]; 2] {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        [[self.m11, self.m12], [self.m12, self.m22]]
    }
    fn force(&self) -> [Float; 2] {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        [0.0, -self.m22 * self.g]
    }
    fn constraints(&self, [x, y]: [Float; 2]) -> [Float; 1] {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        [x * x + y * y - 1.0]
    }
}
#[allow(unused_variables, unused_mut, clippy::all)]
impl ::zeitner::__private::ConstrainedSystem<2, 1> for CoupledMassPendulum {
    const POSITION_CONSTRAINTS: usize = 1;
    const MASS_IS_CONSTANT: bool = true;
    const DYNAMICS_DEPEND_ON_VELOCITY: bool = false;
    const SUMMARY: ::zeitner::__private::SceneSummary = ::zeitner::__private::SceneSummary {
        coordinates: 2,
        position_constraints: 1,
        velocity_constraints: 0,
        mass: ::zeitner::__private::MassKind::ConstantFull,
        time_dependent: false,
        functions: &[
            ::zeitner::__private::FunctionSummary {
                name: "mass_matrix",
                blocks: &[
                    ::zeitner::__private::BlockSummary {
                        name: "m",
                        rows: 2,
                        cols: 2,
                        nonzeros: &[(0, 0), (0, 1), (1, 0), (1, 1)],
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
                        rows: 1,
                        cols: 1,
                        nonzeros: &[(0, 0)],
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
                name: "constraint_jacobian",
                blocks: &[
                    ::zeitner::__private::BlockSummary {
                        name: "g",
                        rows: 1,
                        cols: 2,
                        nonzeros: &[(0, 0), (0, 1)],
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
                        rows: 1,
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
                        rows: 2,
                        cols: 2,
                        nonzeros: &[(0, 0), (0, 1), (1, 0), (1, 1)],
                    },
                    ::zeitner::__private::BlockSummary {
                        name: "f",
                        rows: 2,
                        cols: 1,
                        nonzeros: &[(1, 0)],
                    },
                    ::zeitner::__private::BlockSummary {
                        name: "g",
                        rows: 1,
                        cols: 2,
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
                    adds: 2u64,
                    muls: 7u64,
                    divs: 0u64,
                    transcendental: 0u64,
                    opaque_calls: 0u64,
                },
                ops_unshared: ::zeitner::__private::OpCounts {
                    adds: 2u64,
                    muls: 7u64,
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
                        nonzeros: &[(0, 0), (1, 1)],
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
        ],
    };
    type Mass = ::zeitner::__private::FullMass<2>;
    type Storage = ::zeitner::__private::Dense;
    const SPARSITY: ::core::option::Option<::zeitner::__private::Sparsity> = ::core::option::Option::Some(::zeitner::__private::Sparsity {
        constraint_jacobian: &[(0, 0), (0, 1)],
        force_jacobians: [&[], &[]],
        constraint_force_jacobians: [&[(0, 0), (1, 1)], &[]],
    });
    #[inline]
    fn mass_matrix(
        &self,
        q: &::zeitner::__private::Vector<2>,
        t: ::zeitner::__private::Float,
    ) -> Self::Mass {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let mut m = ::zeitner::__private::Matrix::<2, 2>::zeros();
        m[(0, 0)] = self.m11;
        m[(0, 1)] = self.m12;
        m[(1, 0)] = self.m12;
        m[(1, 1)] = self.m22;
        ::zeitner::__private::FullMass(m)
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
        f[1] = -(self.m22 * self.g);
        f
    }
    #[inline]
    fn constraint_residual(
        &self,
        q: &::zeitner::__private::Vector<2>,
        v: &::zeitner::__private::Vector<2>,
        t: ::zeitner::__private::Float,
    ) -> ::zeitner::__private::Vector<1> {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let mut g = ::zeitner::__private::Vector::<1>::zeros();
        g[0] = q[0].powi(2) + q[1].powi(2) - 1.0;
        g
    }
    #[inline]
    fn constraint_jacobian(
        &self,
        q: &::zeitner::__private::Vector<2>,
        v: &::zeitner::__private::Vector<2>,
        t: ::zeitner::__private::Float,
    ) -> ::zeitner::__private::Matrix<1, 2> {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let mut g = ::zeitner::__private::Matrix::<1, 2>::zeros();
        g[(0, 0)] = 2.0 * q[0];
        g[(0, 1)] = 2.0 * q[1];
        g
    }
    #[inline]
    fn constraint_rate(
        &self,
        q: &::zeitner::__private::Vector<2>,
        v: &::zeitner::__private::Vector<2>,
        t: ::zeitner::__private::Float,
    ) -> ::zeitner::__private::Vector<1> {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let mut w = ::zeitner::__private::Vector::<1>::zeros();
        w[0] = 2.0 * q[0] * v[0] + 2.0 * q[1] * v[1];
        w
    }
    #[inline]
    fn constraint_acceleration_bias(
        &self,
        q: &::zeitner::__private::Vector<2>,
        v: &::zeitner::__private::Vector<2>,
        t: ::zeitner::__private::Float,
    ) -> ::zeitner::__private::Vector<1> {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let mut b = ::zeitner::__private::Vector::<1>::zeros();
        b[0] = v[0] * (2.0 * v[0]) + v[1] * (2.0 * v[1]);
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
        ::zeitner::__private::Matrix<1, 2>,
        ::zeitner::__private::Vector<1>,
    ) {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let mut m = ::zeitner::__private::Matrix::<2, 2>::zeros();
        let mut f = ::zeitner::__private::Vector::<2>::zeros();
        let mut g = ::zeitner::__private::Matrix::<1, 2>::zeros();
        let mut b = ::zeitner::__private::Vector::<1>::zeros();
        m[(0, 0)] = self.m11;
        m[(0, 1)] = self.m12;
        m[(1, 0)] = self.m12;
        m[(1, 1)] = self.m22;
        f[1] = -(self.m22 * self.g);
        g[(0, 0)] = 2.0 * q[0];
        g[(0, 1)] = 2.0 * q[1];
        b[0] = v[0] * (2.0 * v[0]) + v[1] * (2.0 * v[1]);
        (::zeitner::__private::FullMass(m), f, g, b)
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
        lambda: &::zeitner::__private::Vector<1>,
    ) -> (::zeitner::__private::Matrix<2, 2>, ::zeitner::__private::Matrix<2, 2>) {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let s0 = 2.0 * lambda[0];
        let mut dq = ::zeitner::__private::Matrix::<2, 2>::zeros();
        let mut dv = ::zeitner::__private::Matrix::<2, 2>::zeros();
        dq[(0, 0)] = s0;
        dq[(1, 1)] = s0;
        (dq, dv)
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
        values[0] = 2.0 * q[0];
        values[1] = 2.0 * q[1];
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
        lambda: &::zeitner::__private::Vector<1>,
        values: &mut [::zeitner::__private::Float],
    ) {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let s0 = 2.0 * lambda[0];
        values[0] = s0;
        values[1] = s0;
    }
}
#[allow(dead_code)]
impl CuspBead {
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
    fn constraints(&self, [x, y]: [Float; 2]) -> [Float; 1] {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        [y * y - x * x * x]
    }
}
#[allow(unused_variables, unused_mut, clippy::all)]
impl ::zeitner::__private::ConstrainedSystem<2, 1> for CuspBead {
    const POSITION_CONSTRAINTS: usize = 1;
    const MASS_IS_CONSTANT: bool = true;
    const DYNAMICS_DEPEND_ON_VELOCITY: bool = false;
    const SUMMARY: ::zeitner::__private::SceneSummary = ::zeitner::__private::SceneSummary {
        coordinates: 2,
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
                        rows: 1,
                        cols: 1,
                        nonzeros: &[(0, 0)],
                    },
                ],
                ops: ::zeitner::__private::OpCounts {
                    adds: 1u64,
                    muls: 3u64,
                    divs: 0u64,
                    transcendental: 0u64,
                    opaque_calls: 0u64,
                },
                ops_unshared: ::zeitner::__private::OpCounts {
                    adds: 1u64,
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
                        cols: 2,
                        nonzeros: &[(0, 0), (0, 1)],
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
                    adds: 2u64,
                    muls: 6u64,
                    divs: 0u64,
                    transcendental: 0u64,
                    opaque_calls: 0u64,
                },
                ops_unshared: ::zeitner::__private::OpCounts {
                    adds: 2u64,
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
                        rows: 1,
                        cols: 1,
                        nonzeros: &[(0, 0)],
                    },
                ],
                ops: ::zeitner::__private::OpCounts {
                    adds: 2u64,
                    muls: 6u64,
                    divs: 0u64,
                    transcendental: 0u64,
                    opaque_calls: 0u64,
                },
                ops_unshared: ::zeitner::__private::OpCounts {
                    adds: 2u64,
                    muls: 7u64,
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
                        rows: 1,
                        cols: 2,
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
                    adds: 5u64,
                    muls: 10u64,
                    divs: 0u64,
                    transcendental: 0u64,
                    opaque_calls: 0u64,
                },
                ops_unshared: ::zeitner::__private::OpCounts {
                    adds: 5u64,
                    muls: 12u64,
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
                        nonzeros: &[(0, 0), (1, 1)],
                    },
                    ::zeitner::__private::BlockSummary {
                        name: "dv",
                        rows: 2,
                        cols: 2,
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
                    muls: 5u64,
                    divs: 0u64,
                    transcendental: 0u64,
                    opaque_calls: 0u64,
                },
            },
        ],
    };
    type Mass = ::zeitner::__private::DiagonalMass<2>;
    type Storage = ::zeitner::__private::Dense;
    const SPARSITY: ::core::option::Option<::zeitner::__private::Sparsity> = ::core::option::Option::Some(::zeitner::__private::Sparsity {
        constraint_jacobian: &[(0, 0), (0, 1)],
        force_jacobians: [&[], &[]],
        constraint_force_jacobians: [&[(0, 0), (1, 1)], &[]],
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
    ) -> ::zeitner::__private::Vector<1> {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let mut g = ::zeitner::__private::Vector::<1>::zeros();
        g[0] = q[1].powi(2) - q[0] * q[0].powi(2);
        g
    }
    #[inline]
    fn constraint_jacobian(
        &self,
        q: &::zeitner::__private::Vector<2>,
        v: &::zeitner::__private::Vector<2>,
        t: ::zeitner::__private::Float,
    ) -> ::zeitner::__private::Matrix<1, 2> {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let mut g = ::zeitner::__private::Matrix::<1, 2>::zeros();
        g[(0, 0)] = -(q[0].powi(2) + q[0] * (2.0 * q[0]));
        g[(0, 1)] = 2.0 * q[1];
        g
    }
    #[inline]
    fn constraint_rate(
        &self,
        q: &::zeitner::__private::Vector<2>,
        v: &::zeitner::__private::Vector<2>,
        t: ::zeitner::__private::Float,
    ) -> ::zeitner::__private::Vector<1> {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let mut w = ::zeitner::__private::Vector::<1>::zeros();
        w[0] = 2.0 * q[1] * v[1] - (q[0].powi(2) + q[0] * (2.0 * q[0])) * v[0];
        w
    }
    #[inline]
    fn constraint_acceleration_bias(
        &self,
        q: &::zeitner::__private::Vector<2>,
        v: &::zeitner::__private::Vector<2>,
        t: ::zeitner::__private::Float,
    ) -> ::zeitner::__private::Vector<1> {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let s0 = 2.0 * q[0];
        let mut b = ::zeitner::__private::Vector::<1>::zeros();
        b[0] = v[1] * (2.0 * v[1]) - v[0] * (v[0] * (s0 + 2.0 * s0));
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
        ::zeitner::__private::Matrix<1, 2>,
        ::zeitner::__private::Vector<1>,
    ) {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let s0 = 2.0 * q[0];
        let mut m = ::zeitner::__private::Vector::<2>::zeros();
        let mut f = ::zeitner::__private::Vector::<2>::zeros();
        let mut g = ::zeitner::__private::Matrix::<1, 2>::zeros();
        let mut b = ::zeitner::__private::Vector::<1>::zeros();
        m[0] = self.m;
        m[1] = self.m;
        f[1] = -(self.m * self.g);
        g[(0, 0)] = -(q[0].powi(2) + q[0] * s0);
        g[(0, 1)] = 2.0 * q[1];
        b[0] = v[1] * (2.0 * v[1]) - v[0] * (v[0] * (s0 + 2.0 * s0));
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
        lambda: &::zeitner::__private::Vector<1>,
    ) -> (::zeitner::__private::Matrix<2, 2>, ::zeitner::__private::Matrix<2, 2>) {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let s0 = 2.0 * q[0];
        let mut dq = ::zeitner::__private::Matrix::<2, 2>::zeros();
        let mut dv = ::zeitner::__private::Matrix::<2, 2>::zeros();
        dq[(0, 0)] = -((s0 + 2.0 * s0) * lambda[0]);
        dq[(1, 1)] = 2.0 * lambda[0];
        (dq, dv)
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
        values[0] = -(q[0].powi(2) + q[0] * (2.0 * q[0]));
        values[1] = 2.0 * q[1];
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
        lambda: &::zeitner::__private::Vector<1>,
        values: &mut [::zeitner::__private::Float],
    ) {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let s0 = 2.0 * q[0];
        values[0] = -((s0 + 2.0 * s0) * lambda[0]);
        values[1] = 2.0 * lambda[0];
    }
}
