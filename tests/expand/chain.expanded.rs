#[allow(dead_code)]
impl Chain2 {
    fn mass(&self) -> [f64; 4] {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        [self.m, self.m, self.m, self.m]
    }
    fn force(&self) -> [f64; 4] {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        [0.0, -self.m * self.g, 0.0, -self.m * self.g]
    }
    fn constraints(&self, q: [f64; 4]) -> [f64; 2] {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        [
            q[0] * q[0] + q[1] * q[1] - self.l * self.l,
            (q[2] - q[0]).powi(2) + (q[3] - q[1]).powi(2) - self.l * self.l,
        ]
    }
}
#[allow(unused_variables, unused_mut, clippy::all)]
impl ::zeitner::__private::ConstrainedSystem<4, 2> for Chain2 {
    const POSITION_CONSTRAINTS: usize = 2;
    const MASS_IS_CONSTANT: bool = true;
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
    #[inline]
    fn mass_matrix(&self, q: &::zeitner::__private::Vector<4>, t: f64) -> Self::Mass {
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
        t: f64,
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
        t: f64,
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
        t: f64,
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
        t: f64,
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
        t: f64,
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
    fn force_jacobians(
        &self,
        q: &::zeitner::__private::Vector<4>,
        v: &::zeitner::__private::Vector<4>,
        t: f64,
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
        t: f64,
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
}
#[allow(dead_code)]
impl Chain4 {
    fn mass(&self) -> [f64; 8] {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        [self.m, self.m, self.m, self.m, self.m, self.m, self.m, self.m]
    }
    fn force(&self) -> [f64; 8] {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        [
            0.0,
            -self.m * self.g,
            0.0,
            -self.m * self.g,
            0.0,
            -self.m * self.g,
            0.0,
            -self.m * self.g,
        ]
    }
    fn constraints(&self, q: [f64; 8]) -> [f64; 4] {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        [
            q[0] * q[0] + q[1] * q[1] - self.l * self.l,
            (q[2] - q[0]).powi(2) + (q[3] - q[1]).powi(2) - self.l * self.l,
            (q[4] - q[2]).powi(2) + (q[5] - q[3]).powi(2) - self.l * self.l,
            (q[6] - q[4]).powi(2) + (q[7] - q[5]).powi(2) - self.l * self.l,
        ]
    }
}
#[allow(unused_variables, unused_mut, clippy::all)]
impl ::zeitner::__private::ConstrainedSystem<8, 4> for Chain4 {
    const POSITION_CONSTRAINTS: usize = 4;
    const MASS_IS_CONSTANT: bool = true;
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
    #[inline]
    fn mass_matrix(&self, q: &::zeitner::__private::Vector<8>, t: f64) -> Self::Mass {
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
        t: f64,
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
        t: f64,
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
        t: f64,
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
        t: f64,
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
        t: f64,
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
    fn force_jacobians(
        &self,
        q: &::zeitner::__private::Vector<8>,
        v: &::zeitner::__private::Vector<8>,
        t: f64,
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
        t: f64,
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
}
#[allow(dead_code)]
impl Chain8 {
    fn mass(&self) -> [f64; 16] {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        [
            self.m,
            self.m,
            self.m,
            self.m,
            self.m,
            self.m,
            self.m,
            self.m,
            self.m,
            self.m,
            self.m,
            self.m,
            self.m,
            self.m,
            self.m,
            self.m,
        ]
    }
    fn force(&self) -> [f64; 16] {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        [
            0.0,
            -self.m * self.g,
            0.0,
            -self.m * self.g,
            0.0,
            -self.m * self.g,
            0.0,
            -self.m * self.g,
            0.0,
            -self.m * self.g,
            0.0,
            -self.m * self.g,
            0.0,
            -self.m * self.g,
            0.0,
            -self.m * self.g,
        ]
    }
    fn constraints(&self, q: [f64; 16]) -> [f64; 8] {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        [
            q[0] * q[0] + q[1] * q[1] - self.l * self.l,
            (q[2] - q[0]).powi(2) + (q[3] - q[1]).powi(2) - self.l * self.l,
            (q[4] - q[2]).powi(2) + (q[5] - q[3]).powi(2) - self.l * self.l,
            (q[6] - q[4]).powi(2) + (q[7] - q[5]).powi(2) - self.l * self.l,
            (q[8] - q[6]).powi(2) + (q[9] - q[7]).powi(2) - self.l * self.l,
            (q[10] - q[8]).powi(2) + (q[11] - q[9]).powi(2) - self.l * self.l,
            (q[12] - q[10]).powi(2) + (q[13] - q[11]).powi(2) - self.l * self.l,
            (q[14] - q[12]).powi(2) + (q[15] - q[13]).powi(2) - self.l * self.l,
        ]
    }
}
#[allow(unused_variables, unused_mut, clippy::all)]
impl ::zeitner::__private::ConstrainedSystem<16, 8> for Chain8 {
    const POSITION_CONSTRAINTS: usize = 8;
    const MASS_IS_CONSTANT: bool = true;
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
    #[inline]
    fn mass_matrix(&self, q: &::zeitner::__private::Vector<16>, t: f64) -> Self::Mass {
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
        t: f64,
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
        t: f64,
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
        t: f64,
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
        t: f64,
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
        t: f64,
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
    fn force_jacobians(
        &self,
        q: &::zeitner::__private::Vector<16>,
        v: &::zeitner::__private::Vector<16>,
        t: f64,
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
        t: f64,
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
}
#[allow(dead_code)]
impl Chain16 {
    fn mass(&self) -> [f64; 32] {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        [
            self.m,
            self.m,
            self.m,
            self.m,
            self.m,
            self.m,
            self.m,
            self.m,
            self.m,
            self.m,
            self.m,
            self.m,
            self.m,
            self.m,
            self.m,
            self.m,
            self.m,
            self.m,
            self.m,
            self.m,
            self.m,
            self.m,
            self.m,
            self.m,
            self.m,
            self.m,
            self.m,
            self.m,
            self.m,
            self.m,
            self.m,
            self.m,
        ]
    }
    fn force(&self) -> [f64; 32] {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        [
            0.0,
            -self.m * self.g,
            0.0,
            -self.m * self.g,
            0.0,
            -self.m * self.g,
            0.0,
            -self.m * self.g,
            0.0,
            -self.m * self.g,
            0.0,
            -self.m * self.g,
            0.0,
            -self.m * self.g,
            0.0,
            -self.m * self.g,
            0.0,
            -self.m * self.g,
            0.0,
            -self.m * self.g,
            0.0,
            -self.m * self.g,
            0.0,
            -self.m * self.g,
            0.0,
            -self.m * self.g,
            0.0,
            -self.m * self.g,
            0.0,
            -self.m * self.g,
            0.0,
            -self.m * self.g,
        ]
    }
    fn constraints(&self, q: [f64; 32]) -> [f64; 16] {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        [
            q[0] * q[0] + q[1] * q[1] - self.l * self.l,
            (q[2] - q[0]).powi(2) + (q[3] - q[1]).powi(2) - self.l * self.l,
            (q[4] - q[2]).powi(2) + (q[5] - q[3]).powi(2) - self.l * self.l,
            (q[6] - q[4]).powi(2) + (q[7] - q[5]).powi(2) - self.l * self.l,
            (q[8] - q[6]).powi(2) + (q[9] - q[7]).powi(2) - self.l * self.l,
            (q[10] - q[8]).powi(2) + (q[11] - q[9]).powi(2) - self.l * self.l,
            (q[12] - q[10]).powi(2) + (q[13] - q[11]).powi(2) - self.l * self.l,
            (q[14] - q[12]).powi(2) + (q[15] - q[13]).powi(2) - self.l * self.l,
            (q[16] - q[14]).powi(2) + (q[17] - q[15]).powi(2) - self.l * self.l,
            (q[18] - q[16]).powi(2) + (q[19] - q[17]).powi(2) - self.l * self.l,
            (q[20] - q[18]).powi(2) + (q[21] - q[19]).powi(2) - self.l * self.l,
            (q[22] - q[20]).powi(2) + (q[23] - q[21]).powi(2) - self.l * self.l,
            (q[24] - q[22]).powi(2) + (q[25] - q[23]).powi(2) - self.l * self.l,
            (q[26] - q[24]).powi(2) + (q[27] - q[25]).powi(2) - self.l * self.l,
            (q[28] - q[26]).powi(2) + (q[29] - q[27]).powi(2) - self.l * self.l,
            (q[30] - q[28]).powi(2) + (q[31] - q[29]).powi(2) - self.l * self.l,
        ]
    }
}
#[allow(unused_variables, unused_mut, clippy::all)]
impl ::zeitner::__private::ConstrainedSystem<32, 16> for Chain16 {
    const POSITION_CONSTRAINTS: usize = 16;
    const MASS_IS_CONSTANT: bool = true;
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
    #[inline]
    fn mass_matrix(&self, q: &::zeitner::__private::Vector<32>, t: f64) -> Self::Mass {
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
        t: f64,
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
        t: f64,
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
        t: f64,
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
        t: f64,
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
        t: f64,
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
    fn force_jacobians(
        &self,
        q: &::zeitner::__private::Vector<32>,
        v: &::zeitner::__private::Vector<32>,
        t: f64,
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
        t: f64,
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
}
