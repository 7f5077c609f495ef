#[allow(dead_code)]
impl Ball {
    fn mass(&self) -> [Float; 1] {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        [self.m]
    }
    fn force(&self) -> [Float; 1] {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        [-self.m * self.g]
    }
    fn gaps(&self, [y]: [Float; 1]) -> [Float; 1] {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        [y]
    }
    fn restitution(&self) -> [Float; 1] {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        [self.e]
    }
    fn parameters(&self) -> [Float; 2] {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        [self.g, self.m]
    }
}
#[allow(unused_variables, unused_mut, clippy::all)]
impl ::zeitner::__private::ConstrainedSystem<1, 1> for Ball {
    const POSITION_CONSTRAINTS: usize = 1;
    const MASS_IS_CONSTANT: bool = true;
    const DYNAMICS_DEPEND_ON_VELOCITY: bool = false;
    const SUMMARY: ::zeitner::__private::SceneSummary = ::zeitner::__private::SceneSummary {
        coordinates: 1,
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
                name: "applied_force",
                blocks: &[
                    ::zeitner::__private::BlockSummary {
                        name: "f",
                        rows: 1,
                        cols: 1,
                        nonzeros: &[(0, 0)],
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
                        rows: 1,
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
                        rows: 1,
                        cols: 1,
                        nonzeros: &[(0, 0)],
                    },
                    ::zeitner::__private::BlockSummary {
                        name: "f",
                        rows: 1,
                        cols: 1,
                        nonzeros: &[(0, 0)],
                    },
                    ::zeitner::__private::BlockSummary {
                        name: "g",
                        rows: 1,
                        cols: 1,
                        nonzeros: &[(0, 0)],
                    },
                    ::zeitner::__private::BlockSummary {
                        name: "b",
                        rows: 1,
                        cols: 1,
                        nonzeros: &[],
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
                name: "force_jacobians",
                blocks: &[
                    ::zeitner::__private::BlockSummary {
                        name: "dq",
                        rows: 1,
                        cols: 1,
                        nonzeros: &[],
                    },
                    ::zeitner::__private::BlockSummary {
                        name: "dv",
                        rows: 1,
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
                name: "constraint_force_jacobians",
                blocks: &[
                    ::zeitner::__private::BlockSummary {
                        name: "dq",
                        rows: 1,
                        cols: 1,
                        nonzeros: &[],
                    },
                    ::zeitner::__private::BlockSummary {
                        name: "dv",
                        rows: 1,
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
                name: "rate_jacobians",
                blocks: &[
                    ::zeitner::__private::BlockSummary {
                        name: "wq",
                        rows: 1,
                        cols: 1,
                        nonzeros: &[],
                    },
                    ::zeitner::__private::BlockSummary {
                        name: "wv",
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
                name: "acceleration_constraint_jacobians",
                blocks: &[
                    ::zeitner::__private::BlockSummary {
                        name: "cq",
                        rows: 1,
                        cols: 1,
                        nonzeros: &[],
                    },
                    ::zeitner::__private::BlockSummary {
                        name: "cv",
                        rows: 1,
                        cols: 1,
                        nonzeros: &[],
                    },
                    ::zeitner::__private::BlockSummary {
                        name: "cp",
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
                        rows: 1,
                        cols: 2,
                        nonzeros: &[(0, 0), (0, 1)],
                    },
                ],
                ops: ::zeitner::__private::OpCounts {
                    adds: 3u64,
                    muls: 0u64,
                    divs: 0u64,
                    transcendental: 0u64,
                    opaque_calls: 0u64,
                },
                ops_unshared: ::zeitner::__private::OpCounts {
                    adds: 3u64,
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
        ],
    };
    type Mass = ::zeitner::__private::DiagonalMass<1>;
    type Storage = ::zeitner::__private::Dense;
    const UNILATERAL_CONSTRAINTS: usize = 1usize;
    const SPARSITY: ::core::option::Option<::zeitner::__private::Sparsity> = ::core::option::Option::Some(::zeitner::__private::Sparsity {
        constraint_jacobian: &[(0, 0)],
        force_jacobians: [&[], &[]],
        constraint_force_jacobians: [&[], &[]],
    });
    #[inline]
    fn mass_matrix(
        &self,
        q: &::zeitner::__private::Vector<1>,
        t: ::zeitner::__private::Float,
    ) -> Self::Mass {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let mut m = ::zeitner::__private::Vector::<1>::zeros();
        m[0] = self.m;
        ::zeitner::__private::DiagonalMass(m)
    }
    #[inline]
    fn applied_force(
        &self,
        q: &::zeitner::__private::Vector<1>,
        v: &::zeitner::__private::Vector<1>,
        t: ::zeitner::__private::Float,
    ) -> ::zeitner::__private::Vector<1> {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let mut f = ::zeitner::__private::Vector::<1>::zeros();
        f[0] = -(self.m * self.g);
        f
    }
    #[inline]
    fn constraint_residual(
        &self,
        q: &::zeitner::__private::Vector<1>,
        v: &::zeitner::__private::Vector<1>,
        t: ::zeitner::__private::Float,
    ) -> ::zeitner::__private::Vector<1> {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let mut g = ::zeitner::__private::Vector::<1>::zeros();
        g[0] = q[0];
        g
    }
    #[inline]
    fn constraint_jacobian(
        &self,
        q: &::zeitner::__private::Vector<1>,
        v: &::zeitner::__private::Vector<1>,
        t: ::zeitner::__private::Float,
    ) -> ::zeitner::__private::Matrix<1, 1> {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let mut g = ::zeitner::__private::Vector::<1>::zeros();
        g[0] = 1.0;
        g
    }
    #[inline]
    fn constraint_rate(
        &self,
        q: &::zeitner::__private::Vector<1>,
        v: &::zeitner::__private::Vector<1>,
        t: ::zeitner::__private::Float,
    ) -> ::zeitner::__private::Vector<1> {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let mut w = ::zeitner::__private::Vector::<1>::zeros();
        w[0] = v[0];
        w
    }
    #[inline]
    fn constraint_acceleration_bias(
        &self,
        q: &::zeitner::__private::Vector<1>,
        v: &::zeitner::__private::Vector<1>,
        t: ::zeitner::__private::Float,
    ) -> ::zeitner::__private::Vector<1> {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let mut b = ::zeitner::__private::Vector::<1>::zeros();
        b
    }
    #[inline]
    fn stage(
        &self,
        q: &::zeitner::__private::Vector<1>,
        v: &::zeitner::__private::Vector<1>,
        t: ::zeitner::__private::Float,
    ) -> (
        Self::Mass,
        ::zeitner::__private::Vector<1>,
        ::zeitner::__private::Matrix<1, 1>,
        ::zeitner::__private::Vector<1>,
    ) {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let mut m = ::zeitner::__private::Vector::<1>::zeros();
        let mut f = ::zeitner::__private::Vector::<1>::zeros();
        let mut g = ::zeitner::__private::Vector::<1>::zeros();
        let mut b = ::zeitner::__private::Vector::<1>::zeros();
        m[0] = self.m;
        f[0] = -(self.m * self.g);
        g[0] = 1.0;
        (::zeitner::__private::DiagonalMass(m), f, g, b)
    }
    #[inline]
    fn force_jacobians(
        &self,
        q: &::zeitner::__private::Vector<1>,
        v: &::zeitner::__private::Vector<1>,
        t: ::zeitner::__private::Float,
    ) -> (::zeitner::__private::Matrix<1, 1>, ::zeitner::__private::Matrix<1, 1>) {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let mut dq = ::zeitner::__private::Vector::<1>::zeros();
        let mut dv = ::zeitner::__private::Vector::<1>::zeros();
        (dq, dv)
    }
    #[inline]
    fn constraint_force_jacobians(
        &self,
        q: &::zeitner::__private::Vector<1>,
        v: &::zeitner::__private::Vector<1>,
        t: ::zeitner::__private::Float,
        lambda: &::zeitner::__private::Vector<1>,
    ) -> (::zeitner::__private::Matrix<1, 1>, ::zeitner::__private::Matrix<1, 1>) {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let mut dq = ::zeitner::__private::Vector::<1>::zeros();
        let mut dv = ::zeitner::__private::Vector::<1>::zeros();
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
    fn constraint_jacobian_nonzeros(
        &self,
        q: &::zeitner::__private::Vector<1>,
        v: &::zeitner::__private::Vector<1>,
        t: ::zeitner::__private::Float,
        values: &mut [::zeitner::__private::Float],
    ) {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        values[0] = 1.0;
    }
    #[inline]
    fn force_jacobian_nonzeros(
        &self,
        q: &::zeitner::__private::Vector<1>,
        v: &::zeitner::__private::Vector<1>,
        t: ::zeitner::__private::Float,
        values: &mut [::zeitner::__private::Float],
    ) {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
    }
    #[inline]
    fn constraint_force_jacobian_nonzeros(
        &self,
        q: &::zeitner::__private::Vector<1>,
        v: &::zeitner::__private::Vector<1>,
        t: ::zeitner::__private::Float,
        lambda: &::zeitner::__private::Vector<1>,
        values: &mut [::zeitner::__private::Float],
    ) {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
    }
}
#[allow(unused_variables, unused_mut, clippy::all)]
impl ::zeitner::__private::ParametrisedSystem<1, 1, 2> for Ball {
    const PARAMETER_NAMES: [&'static str; 2] = ["g", "m"];
    #[inline]
    fn parameter_values(&self) -> ::zeitner::__private::Vector<2> {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let mut theta = ::zeitner::__private::Vector::<2>::zeros();
        theta[0] = self.g;
        theta[1] = self.m;
        theta
    }
    #[inline]
    fn parameter_force(
        &self,
        q: &::zeitner::__private::Vector<1>,
        v: &::zeitner::__private::Vector<1>,
        t: ::zeitner::__private::Float,
        lambda: &::zeitner::__private::Vector<1>,
        a: &::zeitner::__private::Vector<1>,
    ) -> ::zeitner::__private::Matrix<1, 2> {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let mut df = ::zeitner::__private::Matrix::<1, 2>::zeros();
        df[(0, 0)] = -self.m;
        df[(0, 1)] = -self.g - a[0];
        df
    }
    #[inline]
    fn parameter_constraints(
        &self,
        q: &::zeitner::__private::Vector<1>,
        v: &::zeitner::__private::Vector<1>,
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
        q: &::zeitner::__private::Vector<1>,
        v: &::zeitner::__private::Vector<1>,
        t: ::zeitner::__private::Float,
    ) -> (::zeitner::__private::Matrix<1, 1>, ::zeitner::__private::Matrix<1, 1>) {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let mut wq = ::zeitner::__private::Vector::<1>::zeros();
        let mut wv = ::zeitner::__private::Vector::<1>::zeros();
        wv[0] = 1.0;
        (wq, wv)
    }
    #[inline]
    fn acceleration_constraint_jacobians(
        &self,
        q: &::zeitner::__private::Vector<1>,
        v: &::zeitner::__private::Vector<1>,
        t: ::zeitner::__private::Float,
        a: &::zeitner::__private::Vector<1>,
    ) -> (
        ::zeitner::__private::Matrix<1, 1>,
        ::zeitner::__private::Matrix<1, 1>,
        ::zeitner::__private::Matrix<1, 2>,
    ) {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let mut cq = ::zeitner::__private::Vector::<1>::zeros();
        let mut cv = ::zeitner::__private::Vector::<1>::zeros();
        let mut cp = ::zeitner::__private::Matrix::<1, 2>::zeros();
        (cq, cv, cp)
    }
}
#[allow(dead_code)]
impl WallPendulum {
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
        [x * x + y * y - self.length * self.length]
    }
    fn gaps(&self, [x, _y]: [Float; 2]) -> [Float; 1] {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        [x]
    }
    fn restitution(&self) -> [Float; 1] {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        [self.e]
    }
    fn events(&self, [_x, y]: [Float; 2]) -> [Float; 1] {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        [y - self.height]
    }
    fn parameters(&self) -> [Float; 2] {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        [self.length, self.g]
    }
}
#[allow(unused_variables, unused_mut, clippy::all)]
impl ::zeitner::__private::ConstrainedSystem<2, 2> for WallPendulum {
    const POSITION_CONSTRAINTS: usize = 2;
    const MASS_IS_CONSTANT: bool = true;
    const DYNAMICS_DEPEND_ON_VELOCITY: bool = false;
    const SUMMARY: ::zeitner::__private::SceneSummary = ::zeitner::__private::SceneSummary {
        coordinates: 2,
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
                        rows: 2,
                        cols: 2,
                        nonzeros: &[(0, 0), (0, 1), (1, 0)],
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
                        rows: 2,
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
                        nonzeros: &[(0, 0), (0, 1), (1, 0)],
                    },
                    ::zeitner::__private::BlockSummary {
                        name: "b",
                        rows: 2,
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
            ::zeitner::__private::FunctionSummary {
                name: "rate_jacobians",
                blocks: &[
                    ::zeitner::__private::BlockSummary {
                        name: "wq",
                        rows: 2,
                        cols: 2,
                        nonzeros: &[(0, 0), (0, 1)],
                    },
                    ::zeitner::__private::BlockSummary {
                        name: "wv",
                        rows: 2,
                        cols: 2,
                        nonzeros: &[(0, 0), (0, 1), (1, 0)],
                    },
                ],
                ops: ::zeitner::__private::OpCounts {
                    adds: 0u64,
                    muls: 4u64,
                    divs: 0u64,
                    transcendental: 0u64,
                    opaque_calls: 0u64,
                },
                ops_unshared: ::zeitner::__private::OpCounts {
                    adds: 0u64,
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
                        cols: 2,
                        nonzeros: &[(0, 0), (0, 1)],
                    },
                    ::zeitner::__private::BlockSummary {
                        name: "cv",
                        rows: 2,
                        cols: 2,
                        nonzeros: &[(0, 0), (0, 1)],
                    },
                    ::zeitner::__private::BlockSummary {
                        name: "cp",
                        rows: 2,
                        cols: 2,
                        nonzeros: &[],
                    },
                ],
                ops: ::zeitner::__private::OpCounts {
                    adds: 0u64,
                    muls: 6u64,
                    divs: 0u64,
                    transcendental: 0u64,
                    opaque_calls: 0u64,
                },
                ops_unshared: ::zeitner::__private::OpCounts {
                    adds: 0u64,
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
                        rows: 2,
                        cols: 2,
                        nonzeros: &[(1, 1)],
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
                name: "parameter_constraints",
                blocks: &[
                    ::zeitner::__private::BlockSummary {
                        name: "dg",
                        rows: 2,
                        cols: 2,
                        nonzeros: &[(0, 0)],
                    },
                    ::zeitner::__private::BlockSummary {
                        name: "dw",
                        rows: 2,
                        cols: 2,
                        nonzeros: &[],
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
                name: "event_jacobians",
                blocks: &[
                    ::zeitner::__private::BlockSummary {
                        name: "hq",
                        rows: 1,
                        cols: 2,
                        nonzeros: &[(0, 1)],
                    },
                    ::zeitner::__private::BlockSummary {
                        name: "hv",
                        rows: 1,
                        cols: 2,
                        nonzeros: &[],
                    },
                    ::zeitner::__private::BlockSummary {
                        name: "ht",
                        rows: 1,
                        cols: 1,
                        nonzeros: &[],
                    },
                    ::zeitner::__private::BlockSummary {
                        name: "hp",
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
    type Mass = ::zeitner::__private::DiagonalMass<2>;
    type Storage = ::zeitner::__private::Dense;
    const UNILATERAL_CONSTRAINTS: usize = 1usize;
    const EVENTS: usize = 1usize;
    const SPARSITY: ::core::option::Option<::zeitner::__private::Sparsity> = ::core::option::Option::Some(::zeitner::__private::Sparsity {
        constraint_jacobian: &[(0, 0), (0, 1), (1, 0)],
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
    ) -> ::zeitner::__private::Vector<2> {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let mut g = ::zeitner::__private::Vector::<2>::zeros();
        g[0] = q[0].powi(2) + q[1].powi(2) - self.length.powi(2);
        g[1] = q[0];
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
        g[(0, 0)] = 2.0 * q[0];
        g[(0, 1)] = 2.0 * q[1];
        g[(1, 0)] = 1.0;
        g
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
        w[0] = 2.0 * q[0] * v[0] + 2.0 * q[1] * v[1];
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
        f[1] = -(self.m * self.g);
        g[(0, 0)] = 2.0 * q[0];
        g[(0, 1)] = 2.0 * q[1];
        g[(1, 0)] = 1.0;
        b[0] = v[0] * (2.0 * v[0]) + v[1] * (2.0 * v[1]);
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
        let s0 = 2.0 * lambda[0];
        let mut dq = ::zeitner::__private::Matrix::<2, 2>::zeros();
        let mut dv = ::zeitner::__private::Matrix::<2, 2>::zeros();
        dq[(0, 0)] = s0;
        dq[(1, 1)] = s0;
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
    fn event_functions(
        &self,
        q: &::zeitner::__private::Vector<2>,
        v: &::zeitner::__private::Vector<2>,
        t: ::zeitner::__private::Float,
        values: &mut [::zeitner::__private::Float],
    ) {
        let e = {
            #[allow(unused_imports)]
            use ::zeitner::__private::Real as _;
            let mut e = ::zeitner::__private::Vector::<1>::zeros();
            e[0] = q[1] - self.height;
            e
        };
        for (value, x) in values.iter_mut().zip(e.iter()) {
            *value = *x;
        }
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
        values[2] = 1.0;
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
        let s0 = 2.0 * lambda[0];
        values[0] = s0;
        values[1] = s0;
    }
}
#[allow(unused_variables, unused_mut, clippy::all)]
impl ::zeitner::__private::ParametrisedSystem<2, 2, 2> for WallPendulum {
    const PARAMETER_NAMES: [&'static str; 2] = ["length", "g"];
    #[inline]
    fn parameter_values(&self) -> ::zeitner::__private::Vector<2> {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let mut theta = ::zeitner::__private::Vector::<2>::zeros();
        theta[0] = self.length;
        theta[1] = self.g;
        theta
    }
    #[inline]
    fn parameter_force(
        &self,
        q: &::zeitner::__private::Vector<2>,
        v: &::zeitner::__private::Vector<2>,
        t: ::zeitner::__private::Float,
        lambda: &::zeitner::__private::Vector<2>,
        a: &::zeitner::__private::Vector<2>,
    ) -> ::zeitner::__private::Matrix<2, 2> {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let mut df = ::zeitner::__private::Matrix::<2, 2>::zeros();
        df[(1, 1)] = -self.m;
        df
    }
    #[inline]
    fn parameter_constraints(
        &self,
        q: &::zeitner::__private::Vector<2>,
        v: &::zeitner::__private::Vector<2>,
        t: ::zeitner::__private::Float,
    ) -> (::zeitner::__private::Matrix<2, 2>, ::zeitner::__private::Matrix<2, 2>) {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let mut dg = ::zeitner::__private::Matrix::<2, 2>::zeros();
        let mut dw = ::zeitner::__private::Matrix::<2, 2>::zeros();
        dg[(0, 0)] = -(2.0 * self.length);
        (dg, dw)
    }
    #[inline]
    fn rate_jacobians(
        &self,
        q: &::zeitner::__private::Vector<2>,
        v: &::zeitner::__private::Vector<2>,
        t: ::zeitner::__private::Float,
    ) -> (::zeitner::__private::Matrix<2, 2>, ::zeitner::__private::Matrix<2, 2>) {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let mut wq = ::zeitner::__private::Matrix::<2, 2>::zeros();
        let mut wv = ::zeitner::__private::Matrix::<2, 2>::zeros();
        wq[(0, 0)] = 2.0 * v[0];
        wq[(0, 1)] = 2.0 * v[1];
        wv[(0, 0)] = 2.0 * q[0];
        wv[(0, 1)] = 2.0 * q[1];
        wv[(1, 0)] = 1.0;
        (wq, wv)
    }
    #[inline]
    fn acceleration_constraint_jacobians(
        &self,
        q: &::zeitner::__private::Vector<2>,
        v: &::zeitner::__private::Vector<2>,
        t: ::zeitner::__private::Float,
        a: &::zeitner::__private::Vector<2>,
    ) -> (
        ::zeitner::__private::Matrix<2, 2>,
        ::zeitner::__private::Matrix<2, 2>,
        ::zeitner::__private::Matrix<2, 2>,
    ) {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let mut cq = ::zeitner::__private::Matrix::<2, 2>::zeros();
        let mut cv = ::zeitner::__private::Matrix::<2, 2>::zeros();
        let mut cp = ::zeitner::__private::Matrix::<2, 2>::zeros();
        cq[(0, 0)] = 2.0 * a[0];
        cq[(0, 1)] = 2.0 * a[1];
        cv[(0, 0)] = 2.0 * (2.0 * v[0]);
        cv[(0, 1)] = 2.0 * (2.0 * v[1]);
        (cq, cv, cp)
    }
    #[inline]
    fn event_gradient(
        &self,
        index: usize,
        q: &::zeitner::__private::Vector<2>,
        v: &::zeitner::__private::Vector<2>,
        t: ::zeitner::__private::Float,
    ) -> ::zeitner::__private::EventGradient<2, 2> {
        if index >= 1 {
            return ::zeitner::__private::EventGradient::unknown();
        }
        let (
            hq,
            hv,
            ht,
            hp,
        ): (
            ::zeitner::__private::Matrix<1, 2>,
            ::zeitner::__private::Matrix<1, 2>,
            ::zeitner::__private::Vector<1>,
            ::zeitner::__private::Matrix<1, 2>,
        ) = {
            #[allow(unused_imports)]
            use ::zeitner::__private::Real as _;
            let mut hq = ::zeitner::__private::Matrix::<1, 2>::zeros();
            let mut hv = ::zeitner::__private::Matrix::<1, 2>::zeros();
            let mut ht = ::zeitner::__private::Vector::<1>::zeros();
            let mut hp = ::zeitner::__private::Matrix::<1, 2>::zeros();
            hq[(0, 1)] = 1.0;
            (hq, hv, ht, hp)
        };
        ::zeitner::__private::EventGradient {
            q: hq.row(index).transpose(),
            v: hv.row(index).transpose(),
            t: ht[index],
            theta: hp.fixed_rows::<1>(index).into_owned(),
        }
    }
}
#[allow(dead_code)]
impl FallingBar {
    fn mass(&self) -> [Float; 3] {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        [self.m, self.m, self.j]
    }
    fn force(&self) -> [Float; 3] {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        [0.0, -self.m * self.g, 0.0]
    }
    fn constraints(&self, [x, _y, _theta]: [Float; 3]) -> [Float; 1] {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        [x]
    }
    fn gaps(&self, [_x, y, theta]: [Float; 3]) -> [Float; 2] {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        [y - self.a * theta.sin(), y + self.a * theta.sin()]
    }
    fn restitution(&self) -> [Float; 2] {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        [self.e, self.e]
    }
    fn parameters(&self) -> [Float; 2] {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        [self.g, self.a]
    }
}
#[allow(unused_variables, unused_mut, clippy::all)]
impl ::zeitner::__private::ConstrainedSystem<3, 3> for FallingBar {
    const POSITION_CONSTRAINTS: usize = 3;
    const MASS_IS_CONSTANT: bool = true;
    const DYNAMICS_DEPEND_ON_VELOCITY: bool = false;
    const SUMMARY: ::zeitner::__private::SceneSummary = ::zeitner::__private::SceneSummary {
        coordinates: 3,
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
                        rows: 3,
                        cols: 1,
                        nonzeros: &[(0, 0), (1, 0), (2, 0)],
                    },
                ],
                ops: ::zeitner::__private::OpCounts {
                    adds: 2u64,
                    muls: 1u64,
                    divs: 0u64,
                    transcendental: 1u64,
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
                name: "constraint_jacobian",
                blocks: &[
                    ::zeitner::__private::BlockSummary {
                        name: "g",
                        rows: 3,
                        cols: 3,
                        nonzeros: &[(0, 0), (1, 1), (1, 2), (2, 1), (2, 2)],
                    },
                ],
                ops: ::zeitner::__private::OpCounts {
                    adds: 1u64,
                    muls: 1u64,
                    divs: 0u64,
                    transcendental: 1u64,
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
                    transcendental: 1u64,
                    opaque_calls: 0u64,
                },
                ops_unshared: ::zeitner::__private::OpCounts {
                    adds: 2u64,
                    muls: 4u64,
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
                        rows: 3,
                        cols: 1,
                        nonzeros: &[(1, 0), (2, 0)],
                    },
                ],
                ops: ::zeitner::__private::OpCounts {
                    adds: 1u64,
                    muls: 3u64,
                    divs: 0u64,
                    transcendental: 1u64,
                    opaque_calls: 0u64,
                },
                ops_unshared: ::zeitner::__private::OpCounts {
                    adds: 1u64,
                    muls: 6u64,
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
                        nonzeros: &[(1, 0)],
                    },
                    ::zeitner::__private::BlockSummary {
                        name: "g",
                        rows: 3,
                        cols: 3,
                        nonzeros: &[(0, 0), (1, 1), (1, 2), (2, 1), (2, 2)],
                    },
                    ::zeitner::__private::BlockSummary {
                        name: "b",
                        rows: 3,
                        cols: 1,
                        nonzeros: &[(1, 0), (2, 0)],
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
                    muls: 9u64,
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
                    adds: 1u64,
                    muls: 3u64,
                    divs: 0u64,
                    transcendental: 1u64,
                    opaque_calls: 0u64,
                },
                ops_unshared: ::zeitner::__private::OpCounts {
                    adds: 1u64,
                    muls: 4u64,
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
                        rows: 3,
                        cols: 3,
                        nonzeros: &[(1, 2), (2, 2)],
                    },
                    ::zeitner::__private::BlockSummary {
                        name: "wv",
                        rows: 3,
                        cols: 3,
                        nonzeros: &[(0, 0), (1, 1), (1, 2), (2, 1), (2, 2)],
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
                    muls: 6u64,
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
                        rows: 3,
                        cols: 3,
                        nonzeros: &[(1, 2), (2, 2)],
                    },
                    ::zeitner::__private::BlockSummary {
                        name: "cv",
                        rows: 3,
                        cols: 3,
                        nonzeros: &[(1, 2), (2, 2)],
                    },
                    ::zeitner::__private::BlockSummary {
                        name: "cp",
                        rows: 3,
                        cols: 2,
                        nonzeros: &[(1, 1), (2, 1)],
                    },
                ],
                ops: ::zeitner::__private::OpCounts {
                    adds: 6u64,
                    muls: 10u64,
                    divs: 0u64,
                    transcendental: 2u64,
                    opaque_calls: 0u64,
                },
                ops_unshared: ::zeitner::__private::OpCounts {
                    adds: 6u64,
                    muls: 22u64,
                    divs: 0u64,
                    transcendental: 10u64,
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
                        rows: 3,
                        cols: 2,
                        nonzeros: &[(1, 0), (2, 1)],
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
                    adds: 2u64,
                    muls: 2u64,
                    divs: 0u64,
                    transcendental: 2u64,
                    opaque_calls: 0u64,
                },
            },
            ::zeitner::__private::FunctionSummary {
                name: "parameter_constraints",
                blocks: &[
                    ::zeitner::__private::BlockSummary {
                        name: "dg",
                        rows: 3,
                        cols: 2,
                        nonzeros: &[(1, 1), (2, 1)],
                    },
                    ::zeitner::__private::BlockSummary {
                        name: "dw",
                        rows: 3,
                        cols: 2,
                        nonzeros: &[(1, 1), (2, 1)],
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
                    muls: 2u64,
                    divs: 0u64,
                    transcendental: 4u64,
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
        ],
    };
    type Mass = ::zeitner::__private::DiagonalMass<3>;
    type Storage = ::zeitner::__private::Dense;
    const UNILATERAL_CONSTRAINTS: usize = 2usize;
    const SPARSITY: ::core::option::Option<::zeitner::__private::Sparsity> = ::core::option::Option::Some(::zeitner::__private::Sparsity {
        constraint_jacobian: &[(0, 0), (1, 1), (1, 2), (2, 1), (2, 2)],
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
        f[1] = -(self.m * self.g);
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
        let s0 = self.a * q[2].sin();
        let mut g = ::zeitner::__private::Vector::<3>::zeros();
        g[0] = q[0];
        g[1] = q[1] - s0;
        g[2] = q[1] + s0;
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
        let s0 = self.a * q[2].cos();
        let mut g = ::zeitner::__private::Matrix::<3, 3>::zeros();
        g[(0, 0)] = 1.0;
        g[(1, 1)] = 1.0;
        g[(1, 2)] = -s0;
        g[(2, 1)] = 1.0;
        g[(2, 2)] = s0;
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
        let s0 = self.a * q[2].cos() * v[2];
        let mut w = ::zeitner::__private::Vector::<3>::zeros();
        w[0] = v[0];
        w[1] = v[1] - s0;
        w[2] = v[1] + s0;
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
        let s0 = v[2] * (self.a * q[2].sin() * v[2]);
        let mut b = ::zeitner::__private::Vector::<3>::zeros();
        b[1] = s0;
        b[2] = -s0;
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
        let s0 = self.a * q[2].cos();
        let s1 = v[2] * (self.a * q[2].sin() * v[2]);
        let mut m = ::zeitner::__private::Vector::<3>::zeros();
        let mut f = ::zeitner::__private::Vector::<3>::zeros();
        let mut g = ::zeitner::__private::Matrix::<3, 3>::zeros();
        let mut b = ::zeitner::__private::Vector::<3>::zeros();
        m[0] = self.m;
        m[1] = self.m;
        m[2] = self.j;
        f[1] = -(self.m * self.g);
        g[(0, 0)] = 1.0;
        g[(1, 1)] = 1.0;
        g[(1, 2)] = -s0;
        g[(2, 1)] = 1.0;
        g[(2, 2)] = s0;
        b[1] = s1;
        b[2] = -s1;
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
        let s0 = self.a * q[2].sin();
        let mut dq = ::zeitner::__private::Matrix::<3, 3>::zeros();
        let mut dv = ::zeitner::__private::Matrix::<3, 3>::zeros();
        dq[(2, 2)] = s0 * lambda[1] - s0 * lambda[2];
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
    fn constraint_jacobian_nonzeros(
        &self,
        q: &::zeitner::__private::Vector<3>,
        v: &::zeitner::__private::Vector<3>,
        t: ::zeitner::__private::Float,
        values: &mut [::zeitner::__private::Float],
    ) {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let s0 = self.a * q[2].cos();
        values[0] = 1.0;
        values[1] = 1.0;
        values[2] = -s0;
        values[3] = 1.0;
        values[4] = s0;
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
        let s0 = self.a * q[2].sin();
        values[0] = s0 * lambda[1] - s0 * lambda[2];
    }
}
#[allow(unused_variables, unused_mut, clippy::all)]
impl ::zeitner::__private::ParametrisedSystem<3, 3, 2> for FallingBar {
    const PARAMETER_NAMES: [&'static str; 2] = ["g", "a"];
    #[inline]
    fn parameter_values(&self) -> ::zeitner::__private::Vector<2> {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let mut theta = ::zeitner::__private::Vector::<2>::zeros();
        theta[0] = self.g;
        theta[1] = self.a;
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
    ) -> ::zeitner::__private::Matrix<3, 2> {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let s0 = q[2].cos();
        let mut df = ::zeitner::__private::Matrix::<3, 2>::zeros();
        df[(1, 0)] = -self.m;
        df[(2, 1)] = s0 * lambda[1] - s0 * lambda[2];
        df
    }
    #[inline]
    fn parameter_constraints(
        &self,
        q: &::zeitner::__private::Vector<3>,
        v: &::zeitner::__private::Vector<3>,
        t: ::zeitner::__private::Float,
    ) -> (::zeitner::__private::Matrix<3, 2>, ::zeitner::__private::Matrix<3, 2>) {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let s0 = q[2].sin();
        let s1 = q[2].cos() * v[2];
        let mut dg = ::zeitner::__private::Matrix::<3, 2>::zeros();
        let mut dw = ::zeitner::__private::Matrix::<3, 2>::zeros();
        dg[(1, 1)] = -s0;
        dg[(2, 1)] = s0;
        dw[(1, 1)] = -s1;
        dw[(2, 1)] = s1;
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
        let s0 = self.a * q[2].cos();
        let s1 = self.a * q[2].sin() * v[2];
        let mut wq = ::zeitner::__private::Matrix::<3, 3>::zeros();
        let mut wv = ::zeitner::__private::Matrix::<3, 3>::zeros();
        wq[(1, 2)] = s1;
        wq[(2, 2)] = -s1;
        wv[(0, 0)] = 1.0;
        wv[(1, 1)] = 1.0;
        wv[(1, 2)] = -s0;
        wv[(2, 1)] = 1.0;
        wv[(2, 2)] = s0;
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
        ::zeitner::__private::Matrix<3, 2>,
    ) {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let s0 = q[2].sin();
        let s1 = self.a * s0;
        let s2 = q[2].cos();
        let s3 = v[2] * (self.a * s2 * v[2]);
        let s4 = s1 * a[2];
        let s5 = 2.0 * (s1 * v[2]);
        let s6 = v[2] * (s0 * v[2]);
        let s7 = s2 * a[2];
        let mut cq = ::zeitner::__private::Matrix::<3, 3>::zeros();
        let mut cv = ::zeitner::__private::Matrix::<3, 3>::zeros();
        let mut cp = ::zeitner::__private::Matrix::<3, 2>::zeros();
        cq[(1, 2)] = s3 + s4;
        cq[(2, 2)] = -s4 - s3;
        cv[(1, 2)] = s5;
        cv[(2, 2)] = -s5;
        cp[(1, 1)] = s6 - s7;
        cp[(2, 1)] = s7 - s6;
        (cq, cv, cp)
    }
}
