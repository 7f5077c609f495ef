#[allow(dead_code)]
impl Ladder8 {
    const BAYS: usize = 8;
    const NODES: usize = 2 * (Self::BAYS + 1);
    /// Rungs, two rails and a diagonal per bay.
    const BARS: usize = (Self::BAYS + 1) + 3 * Self::BAYS;
    /// Squared distance of two points minus a bar's rest length squared.
    fn bar(&self, p: [Float; 2], r: [Float; 2], length2: Float) -> Float {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        (p[0] - r[0]).powi(2) + (p[1] - r[1]).powi(2) - length2
    }
    fn mass(&self) -> [Float; 2 * Self::NODES] {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        [self.m; 2 * Self::NODES]
    }
    fn force(&self) -> [Float; 2 * Self::NODES] {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let mut f = [0.0; 2 * Self::NODES];
        for node in 0..Self::NODES {
            f[2 * node + 1] = -self.m * self.g;
        }
        f
    }
    fn constraints(&self, q: [Float; 2 * Self::NODES]) -> [Float; Self::BARS + 2] {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let a2 = self.a * self.a;
        let mut g = [0.0; Self::BARS + 2];
        let mut row = 0;
        for k in 0..=Self::BAYS {
            let (b, t) = (4 * k, 4 * k + 2);
            g[row] = self.bar([q[b], q[b + 1]], [q[t], q[t + 1]], a2);
            row += 1;
        }
        for k in 0..Self::BAYS {
            let (b, t, nb, nt) = (4 * k, 4 * k + 2, 4 * k + 4, 4 * k + 6);
            g[row] = self.bar([q[b], q[b + 1]], [q[nb], q[nb + 1]], a2);
            g[row + 1] = self.bar([q[t], q[t + 1]], [q[nt], q[nt + 1]], a2);
            g[row + 2] = self.bar([q[b], q[b + 1]], [q[nt], q[nt + 1]], 2.0 * a2);
            row += 3;
        }
        g[row] = q[0];
        g[row + 1] = q[1];
        g
    }
}
#[allow(unused_variables, unused_mut, clippy::all)]
impl ::zeitner::__private::ConstrainedSystem<36, 35> for Ladder8 {
    const POSITION_CONSTRAINTS: usize = 35;
    const MASS_IS_CONSTANT: bool = true;
    const DYNAMICS_DEPEND_ON_VELOCITY: bool = false;
    const SUMMARY: ::zeitner::__private::SceneSummary = ::zeitner::__private::SceneSummary {
        coordinates: 36,
        position_constraints: 35,
        velocity_constraints: 0,
        mass: ::zeitner::__private::MassKind::ConstantDiagonal,
        time_dependent: false,
        functions: &[
            ::zeitner::__private::FunctionSummary {
                name: "mass_matrix",
                blocks: &[
                    ::zeitner::__private::BlockSummary {
                        name: "m",
                        rows: 36,
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
                        rows: 36,
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
                    adds: 18u64,
                    muls: 18u64,
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
                        rows: 35,
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
                        ],
                    },
                ],
                ops: ::zeitner::__private::OpCounts {
                    adds: 132u64,
                    muls: 68u64,
                    divs: 0u64,
                    transcendental: 0u64,
                    opaque_calls: 0u64,
                },
                ops_unshared: ::zeitner::__private::OpCounts {
                    adds: 132u64,
                    muls: 107u64,
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
                        rows: 35,
                        cols: 36,
                        nonzeros: &[
                            (0, 0),
                            (0, 1),
                            (0, 2),
                            (0, 3),
                            (1, 4),
                            (1, 5),
                            (1, 6),
                            (1, 7),
                            (2, 8),
                            (2, 9),
                            (2, 10),
                            (2, 11),
                            (3, 12),
                            (3, 13),
                            (3, 14),
                            (3, 15),
                            (4, 16),
                            (4, 17),
                            (4, 18),
                            (4, 19),
                            (5, 20),
                            (5, 21),
                            (5, 22),
                            (5, 23),
                            (6, 24),
                            (6, 25),
                            (6, 26),
                            (6, 27),
                            (7, 28),
                            (7, 29),
                            (7, 30),
                            (7, 31),
                            (8, 32),
                            (8, 33),
                            (8, 34),
                            (8, 35),
                            (9, 0),
                            (9, 1),
                            (9, 4),
                            (9, 5),
                            (10, 2),
                            (10, 3),
                            (10, 6),
                            (10, 7),
                            (11, 0),
                            (11, 1),
                            (11, 6),
                            (11, 7),
                            (12, 4),
                            (12, 5),
                            (12, 8),
                            (12, 9),
                            (13, 6),
                            (13, 7),
                            (13, 10),
                            (13, 11),
                            (14, 4),
                            (14, 5),
                            (14, 10),
                            (14, 11),
                            (15, 8),
                            (15, 9),
                            (15, 12),
                            (15, 13),
                            (16, 10),
                            (16, 11),
                            (16, 14),
                            (16, 15),
                            (17, 8),
                            (17, 9),
                            (17, 14),
                            (17, 15),
                            (18, 12),
                            (18, 13),
                            (18, 16),
                            (18, 17),
                            (19, 14),
                            (19, 15),
                            (19, 18),
                            (19, 19),
                            (20, 12),
                            (20, 13),
                            (20, 18),
                            (20, 19),
                            (21, 16),
                            (21, 17),
                            (21, 20),
                            (21, 21),
                            (22, 18),
                            (22, 19),
                            (22, 22),
                            (22, 23),
                            (23, 16),
                            (23, 17),
                            (23, 22),
                            (23, 23),
                            (24, 20),
                            (24, 21),
                            (24, 24),
                            (24, 25),
                            (25, 22),
                            (25, 23),
                            (25, 26),
                            (25, 27),
                            (26, 20),
                            (26, 21),
                            (26, 26),
                            (26, 27),
                            (27, 24),
                            (27, 25),
                            (27, 28),
                            (27, 29),
                            (28, 26),
                            (28, 27),
                            (28, 30),
                            (28, 31),
                            (29, 24),
                            (29, 25),
                            (29, 30),
                            (29, 31),
                            (30, 28),
                            (30, 29),
                            (30, 32),
                            (30, 33),
                            (31, 30),
                            (31, 31),
                            (31, 34),
                            (31, 35),
                            (32, 28),
                            (32, 29),
                            (32, 34),
                            (32, 35),
                            (33, 0),
                            (34, 1),
                        ],
                    },
                ],
                ops: ::zeitner::__private::OpCounts {
                    adds: 132u64,
                    muls: 66u64,
                    divs: 0u64,
                    transcendental: 0u64,
                    opaque_calls: 0u64,
                },
                ops_unshared: ::zeitner::__private::OpCounts {
                    adds: 198u64,
                    muls: 132u64,
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
                        rows: 35,
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
                        ],
                    },
                ],
                ops: ::zeitner::__private::OpCounts {
                    adds: 165u64,
                    muls: 198u64,
                    divs: 0u64,
                    transcendental: 0u64,
                    opaque_calls: 0u64,
                },
                ops_unshared: ::zeitner::__private::OpCounts {
                    adds: 231u64,
                    muls: 264u64,
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
                        rows: 35,
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
                        ],
                    },
                ],
                ops: ::zeitner::__private::OpCounts {
                    adds: 231u64,
                    muls: 204u64,
                    divs: 0u64,
                    transcendental: 0u64,
                    opaque_calls: 0u64,
                },
                ops_unshared: ::zeitner::__private::OpCounts {
                    adds: 231u64,
                    muls: 396u64,
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
                        rows: 36,
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
                        ],
                    },
                    ::zeitner::__private::BlockSummary {
                        name: "f",
                        rows: 36,
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
                        ],
                    },
                    ::zeitner::__private::BlockSummary {
                        name: "g",
                        rows: 35,
                        cols: 36,
                        nonzeros: &[
                            (0, 0),
                            (0, 1),
                            (0, 2),
                            (0, 3),
                            (1, 4),
                            (1, 5),
                            (1, 6),
                            (1, 7),
                            (2, 8),
                            (2, 9),
                            (2, 10),
                            (2, 11),
                            (3, 12),
                            (3, 13),
                            (3, 14),
                            (3, 15),
                            (4, 16),
                            (4, 17),
                            (4, 18),
                            (4, 19),
                            (5, 20),
                            (5, 21),
                            (5, 22),
                            (5, 23),
                            (6, 24),
                            (6, 25),
                            (6, 26),
                            (6, 27),
                            (7, 28),
                            (7, 29),
                            (7, 30),
                            (7, 31),
                            (8, 32),
                            (8, 33),
                            (8, 34),
                            (8, 35),
                            (9, 0),
                            (9, 1),
                            (9, 4),
                            (9, 5),
                            (10, 2),
                            (10, 3),
                            (10, 6),
                            (10, 7),
                            (11, 0),
                            (11, 1),
                            (11, 6),
                            (11, 7),
                            (12, 4),
                            (12, 5),
                            (12, 8),
                            (12, 9),
                            (13, 6),
                            (13, 7),
                            (13, 10),
                            (13, 11),
                            (14, 4),
                            (14, 5),
                            (14, 10),
                            (14, 11),
                            (15, 8),
                            (15, 9),
                            (15, 12),
                            (15, 13),
                            (16, 10),
                            (16, 11),
                            (16, 14),
                            (16, 15),
                            (17, 8),
                            (17, 9),
                            (17, 14),
                            (17, 15),
                            (18, 12),
                            (18, 13),
                            (18, 16),
                            (18, 17),
                            (19, 14),
                            (19, 15),
                            (19, 18),
                            (19, 19),
                            (20, 12),
                            (20, 13),
                            (20, 18),
                            (20, 19),
                            (21, 16),
                            (21, 17),
                            (21, 20),
                            (21, 21),
                            (22, 18),
                            (22, 19),
                            (22, 22),
                            (22, 23),
                            (23, 16),
                            (23, 17),
                            (23, 22),
                            (23, 23),
                            (24, 20),
                            (24, 21),
                            (24, 24),
                            (24, 25),
                            (25, 22),
                            (25, 23),
                            (25, 26),
                            (25, 27),
                            (26, 20),
                            (26, 21),
                            (26, 26),
                            (26, 27),
                            (27, 24),
                            (27, 25),
                            (27, 28),
                            (27, 29),
                            (28, 26),
                            (28, 27),
                            (28, 30),
                            (28, 31),
                            (29, 24),
                            (29, 25),
                            (29, 30),
                            (29, 31),
                            (30, 28),
                            (30, 29),
                            (30, 32),
                            (30, 33),
                            (31, 30),
                            (31, 31),
                            (31, 34),
                            (31, 35),
                            (32, 28),
                            (32, 29),
                            (32, 34),
                            (32, 35),
                            (33, 0),
                            (34, 1),
                        ],
                    },
                    ::zeitner::__private::BlockSummary {
                        name: "b",
                        rows: 35,
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
                        ],
                    },
                ],
                ops: ::zeitner::__private::OpCounts {
                    adds: 364u64,
                    muls: 271u64,
                    divs: 0u64,
                    transcendental: 0u64,
                    opaque_calls: 0u64,
                },
                ops_unshared: ::zeitner::__private::OpCounts {
                    adds: 447u64,
                    muls: 546u64,
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
                        rows: 36,
                        cols: 36,
                        nonzeros: &[],
                    },
                    ::zeitner::__private::BlockSummary {
                        name: "dv",
                        rows: 36,
                        cols: 36,
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
                        rows: 36,
                        cols: 36,
                        nonzeros: &[
                            (0, 0),
                            (0, 2),
                            (0, 4),
                            (0, 6),
                            (1, 1),
                            (1, 3),
                            (1, 5),
                            (1, 7),
                            (2, 0),
                            (2, 2),
                            (2, 6),
                            (3, 1),
                            (3, 3),
                            (3, 7),
                            (4, 0),
                            (4, 4),
                            (4, 6),
                            (4, 8),
                            (4, 10),
                            (5, 1),
                            (5, 5),
                            (5, 7),
                            (5, 9),
                            (5, 11),
                            (6, 0),
                            (6, 2),
                            (6, 4),
                            (6, 6),
                            (6, 10),
                            (7, 1),
                            (7, 3),
                            (7, 5),
                            (7, 7),
                            (7, 11),
                            (8, 4),
                            (8, 8),
                            (8, 10),
                            (8, 12),
                            (8, 14),
                            (9, 5),
                            (9, 9),
                            (9, 11),
                            (9, 13),
                            (9, 15),
                            (10, 4),
                            (10, 6),
                            (10, 8),
                            (10, 10),
                            (10, 14),
                            (11, 5),
                            (11, 7),
                            (11, 9),
                            (11, 11),
                            (11, 15),
                            (12, 8),
                            (12, 12),
                            (12, 14),
                            (12, 16),
                            (12, 18),
                            (13, 9),
                            (13, 13),
                            (13, 15),
                            (13, 17),
                            (13, 19),
                            (14, 8),
                            (14, 10),
                            (14, 12),
                            (14, 14),
                            (14, 18),
                            (15, 9),
                            (15, 11),
                            (15, 13),
                            (15, 15),
                            (15, 19),
                            (16, 12),
                            (16, 16),
                            (16, 18),
                            (16, 20),
                            (16, 22),
                            (17, 13),
                            (17, 17),
                            (17, 19),
                            (17, 21),
                            (17, 23),
                            (18, 12),
                            (18, 14),
                            (18, 16),
                            (18, 18),
                            (18, 22),
                            (19, 13),
                            (19, 15),
                            (19, 17),
                            (19, 19),
                            (19, 23),
                            (20, 16),
                            (20, 20),
                            (20, 22),
                            (20, 24),
                            (20, 26),
                            (21, 17),
                            (21, 21),
                            (21, 23),
                            (21, 25),
                            (21, 27),
                            (22, 16),
                            (22, 18),
                            (22, 20),
                            (22, 22),
                            (22, 26),
                            (23, 17),
                            (23, 19),
                            (23, 21),
                            (23, 23),
                            (23, 27),
                            (24, 20),
                            (24, 24),
                            (24, 26),
                            (24, 28),
                            (24, 30),
                            (25, 21),
                            (25, 25),
                            (25, 27),
                            (25, 29),
                            (25, 31),
                            (26, 20),
                            (26, 22),
                            (26, 24),
                            (26, 26),
                            (26, 30),
                            (27, 21),
                            (27, 23),
                            (27, 25),
                            (27, 27),
                            (27, 31),
                            (28, 24),
                            (28, 28),
                            (28, 30),
                            (28, 32),
                            (28, 34),
                            (29, 25),
                            (29, 29),
                            (29, 31),
                            (29, 33),
                            (29, 35),
                            (30, 24),
                            (30, 26),
                            (30, 28),
                            (30, 30),
                            (30, 34),
                            (31, 25),
                            (31, 27),
                            (31, 29),
                            (31, 31),
                            (31, 35),
                            (32, 28),
                            (32, 32),
                            (32, 34),
                            (33, 29),
                            (33, 33),
                            (33, 35),
                            (34, 28),
                            (34, 30),
                            (34, 32),
                            (34, 34),
                            (35, 29),
                            (35, 31),
                            (35, 33),
                            (35, 35),
                        ],
                    },
                    ::zeitner::__private::BlockSummary {
                        name: "dv",
                        rows: 36,
                        cols: 36,
                        nonzeros: &[],
                    },
                ],
                ops: ::zeitner::__private::OpCounts {
                    adds: 89u64,
                    muls: 66u64,
                    divs: 0u64,
                    transcendental: 0u64,
                    opaque_calls: 0u64,
                },
                ops_unshared: ::zeitner::__private::OpCounts {
                    adds: 178u64,
                    muls: 264u64,
                    divs: 0u64,
                    transcendental: 0u64,
                    opaque_calls: 0u64,
                },
            },
        ],
    };
    type Mass = ::zeitner::__private::DiagonalMass<36>;
    type Storage = ::zeitner::__private::Dense;
    const SPARSITY: ::core::option::Option<::zeitner::__private::Sparsity> = ::core::option::Option::Some(::zeitner::__private::Sparsity {
        constraint_jacobian: &[
            (0, 0),
            (0, 1),
            (0, 2),
            (0, 3),
            (1, 4),
            (1, 5),
            (1, 6),
            (1, 7),
            (2, 8),
            (2, 9),
            (2, 10),
            (2, 11),
            (3, 12),
            (3, 13),
            (3, 14),
            (3, 15),
            (4, 16),
            (4, 17),
            (4, 18),
            (4, 19),
            (5, 20),
            (5, 21),
            (5, 22),
            (5, 23),
            (6, 24),
            (6, 25),
            (6, 26),
            (6, 27),
            (7, 28),
            (7, 29),
            (7, 30),
            (7, 31),
            (8, 32),
            (8, 33),
            (8, 34),
            (8, 35),
            (9, 0),
            (9, 1),
            (9, 4),
            (9, 5),
            (10, 2),
            (10, 3),
            (10, 6),
            (10, 7),
            (11, 0),
            (11, 1),
            (11, 6),
            (11, 7),
            (12, 4),
            (12, 5),
            (12, 8),
            (12, 9),
            (13, 6),
            (13, 7),
            (13, 10),
            (13, 11),
            (14, 4),
            (14, 5),
            (14, 10),
            (14, 11),
            (15, 8),
            (15, 9),
            (15, 12),
            (15, 13),
            (16, 10),
            (16, 11),
            (16, 14),
            (16, 15),
            (17, 8),
            (17, 9),
            (17, 14),
            (17, 15),
            (18, 12),
            (18, 13),
            (18, 16),
            (18, 17),
            (19, 14),
            (19, 15),
            (19, 18),
            (19, 19),
            (20, 12),
            (20, 13),
            (20, 18),
            (20, 19),
            (21, 16),
            (21, 17),
            (21, 20),
            (21, 21),
            (22, 18),
            (22, 19),
            (22, 22),
            (22, 23),
            (23, 16),
            (23, 17),
            (23, 22),
            (23, 23),
            (24, 20),
            (24, 21),
            (24, 24),
            (24, 25),
            (25, 22),
            (25, 23),
            (25, 26),
            (25, 27),
            (26, 20),
            (26, 21),
            (26, 26),
            (26, 27),
            (27, 24),
            (27, 25),
            (27, 28),
            (27, 29),
            (28, 26),
            (28, 27),
            (28, 30),
            (28, 31),
            (29, 24),
            (29, 25),
            (29, 30),
            (29, 31),
            (30, 28),
            (30, 29),
            (30, 32),
            (30, 33),
            (31, 30),
            (31, 31),
            (31, 34),
            (31, 35),
            (32, 28),
            (32, 29),
            (32, 34),
            (32, 35),
            (33, 0),
            (34, 1),
        ],
        force_jacobians: [&[], &[]],
        constraint_force_jacobians: [
            &[
                (0, 0),
                (0, 2),
                (0, 4),
                (0, 6),
                (1, 1),
                (1, 3),
                (1, 5),
                (1, 7),
                (2, 0),
                (2, 2),
                (2, 6),
                (3, 1),
                (3, 3),
                (3, 7),
                (4, 0),
                (4, 4),
                (4, 6),
                (4, 8),
                (4, 10),
                (5, 1),
                (5, 5),
                (5, 7),
                (5, 9),
                (5, 11),
                (6, 0),
                (6, 2),
                (6, 4),
                (6, 6),
                (6, 10),
                (7, 1),
                (7, 3),
                (7, 5),
                (7, 7),
                (7, 11),
                (8, 4),
                (8, 8),
                (8, 10),
                (8, 12),
                (8, 14),
                (9, 5),
                (9, 9),
                (9, 11),
                (9, 13),
                (9, 15),
                (10, 4),
                (10, 6),
                (10, 8),
                (10, 10),
                (10, 14),
                (11, 5),
                (11, 7),
                (11, 9),
                (11, 11),
                (11, 15),
                (12, 8),
                (12, 12),
                (12, 14),
                (12, 16),
                (12, 18),
                (13, 9),
                (13, 13),
                (13, 15),
                (13, 17),
                (13, 19),
                (14, 8),
                (14, 10),
                (14, 12),
                (14, 14),
                (14, 18),
                (15, 9),
                (15, 11),
                (15, 13),
                (15, 15),
                (15, 19),
                (16, 12),
                (16, 16),
                (16, 18),
                (16, 20),
                (16, 22),
                (17, 13),
                (17, 17),
                (17, 19),
                (17, 21),
                (17, 23),
                (18, 12),
                (18, 14),
                (18, 16),
                (18, 18),
                (18, 22),
                (19, 13),
                (19, 15),
                (19, 17),
                (19, 19),
                (19, 23),
                (20, 16),
                (20, 20),
                (20, 22),
                (20, 24),
                (20, 26),
                (21, 17),
                (21, 21),
                (21, 23),
                (21, 25),
                (21, 27),
                (22, 16),
                (22, 18),
                (22, 20),
                (22, 22),
                (22, 26),
                (23, 17),
                (23, 19),
                (23, 21),
                (23, 23),
                (23, 27),
                (24, 20),
                (24, 24),
                (24, 26),
                (24, 28),
                (24, 30),
                (25, 21),
                (25, 25),
                (25, 27),
                (25, 29),
                (25, 31),
                (26, 20),
                (26, 22),
                (26, 24),
                (26, 26),
                (26, 30),
                (27, 21),
                (27, 23),
                (27, 25),
                (27, 27),
                (27, 31),
                (28, 24),
                (28, 28),
                (28, 30),
                (28, 32),
                (28, 34),
                (29, 25),
                (29, 29),
                (29, 31),
                (29, 33),
                (29, 35),
                (30, 24),
                (30, 26),
                (30, 28),
                (30, 30),
                (30, 34),
                (31, 25),
                (31, 27),
                (31, 29),
                (31, 31),
                (31, 35),
                (32, 28),
                (32, 32),
                (32, 34),
                (33, 29),
                (33, 33),
                (33, 35),
                (34, 28),
                (34, 30),
                (34, 32),
                (34, 34),
                (35, 29),
                (35, 31),
                (35, 33),
                (35, 35),
            ],
            &[],
        ],
    });
    #[inline]
    fn mass_matrix(
        &self,
        q: &::zeitner::__private::Vector<36>,
        t: ::zeitner::__private::Float,
    ) -> Self::Mass {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let mut m = ::zeitner::__private::Vector::<36>::zeros();
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
        ::zeitner::__private::DiagonalMass(m)
    }
    #[inline]
    fn applied_force(
        &self,
        q: &::zeitner::__private::Vector<36>,
        v: &::zeitner::__private::Vector<36>,
        t: ::zeitner::__private::Float,
    ) -> ::zeitner::__private::Vector<36> {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let s0 = -(self.m * self.g);
        let mut f = ::zeitner::__private::Vector::<36>::zeros();
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
        f
    }
    #[inline]
    fn constraint_residual(
        &self,
        q: &::zeitner::__private::Vector<36>,
        v: &::zeitner::__private::Vector<36>,
        t: ::zeitner::__private::Float,
    ) -> ::zeitner::__private::Vector<35> {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let s0 = self.a.powi(2);
        let s1 = 2.0 * s0;
        let mut g = ::zeitner::__private::Vector::<35>::zeros();
        g[0] = (q[0] - q[2]).powi(2) + (q[1] - q[3]).powi(2) - s0;
        g[1] = (q[4] - q[6]).powi(2) + (q[5] - q[7]).powi(2) - s0;
        g[2] = (q[8] - q[10]).powi(2) + (q[9] - q[11]).powi(2) - s0;
        g[3] = (q[12] - q[14]).powi(2) + (q[13] - q[15]).powi(2) - s0;
        g[4] = (q[16] - q[18]).powi(2) + (q[17] - q[19]).powi(2) - s0;
        g[5] = (q[20] - q[22]).powi(2) + (q[21] - q[23]).powi(2) - s0;
        g[6] = (q[24] - q[26]).powi(2) + (q[25] - q[27]).powi(2) - s0;
        g[7] = (q[28] - q[30]).powi(2) + (q[29] - q[31]).powi(2) - s0;
        g[8] = (q[32] - q[34]).powi(2) + (q[33] - q[35]).powi(2) - s0;
        g[9] = (q[0] - q[4]).powi(2) + (q[1] - q[5]).powi(2) - s0;
        g[10] = (q[2] - q[6]).powi(2) + (q[3] - q[7]).powi(2) - s0;
        g[11] = (q[0] - q[6]).powi(2) + (q[1] - q[7]).powi(2) - s1;
        g[12] = (q[4] - q[8]).powi(2) + (q[5] - q[9]).powi(2) - s0;
        g[13] = (q[6] - q[10]).powi(2) + (q[7] - q[11]).powi(2) - s0;
        g[14] = (q[4] - q[10]).powi(2) + (q[5] - q[11]).powi(2) - s1;
        g[15] = (q[8] - q[12]).powi(2) + (q[9] - q[13]).powi(2) - s0;
        g[16] = (q[10] - q[14]).powi(2) + (q[11] - q[15]).powi(2) - s0;
        g[17] = (q[8] - q[14]).powi(2) + (q[9] - q[15]).powi(2) - s1;
        g[18] = (q[12] - q[16]).powi(2) + (q[13] - q[17]).powi(2) - s0;
        g[19] = (q[14] - q[18]).powi(2) + (q[15] - q[19]).powi(2) - s0;
        g[20] = (q[12] - q[18]).powi(2) + (q[13] - q[19]).powi(2) - s1;
        g[21] = (q[16] - q[20]).powi(2) + (q[17] - q[21]).powi(2) - s0;
        g[22] = (q[18] - q[22]).powi(2) + (q[19] - q[23]).powi(2) - s0;
        g[23] = (q[16] - q[22]).powi(2) + (q[17] - q[23]).powi(2) - s1;
        g[24] = (q[20] - q[24]).powi(2) + (q[21] - q[25]).powi(2) - s0;
        g[25] = (q[22] - q[26]).powi(2) + (q[23] - q[27]).powi(2) - s0;
        g[26] = (q[20] - q[26]).powi(2) + (q[21] - q[27]).powi(2) - s1;
        g[27] = (q[24] - q[28]).powi(2) + (q[25] - q[29]).powi(2) - s0;
        g[28] = (q[26] - q[30]).powi(2) + (q[27] - q[31]).powi(2) - s0;
        g[29] = (q[24] - q[30]).powi(2) + (q[25] - q[31]).powi(2) - s1;
        g[30] = (q[28] - q[32]).powi(2) + (q[29] - q[33]).powi(2) - s0;
        g[31] = (q[30] - q[34]).powi(2) + (q[31] - q[35]).powi(2) - s0;
        g[32] = (q[28] - q[34]).powi(2) + (q[29] - q[35]).powi(2) - s1;
        g[33] = q[0];
        g[34] = q[1];
        g
    }
    #[inline]
    fn constraint_jacobian(
        &self,
        q: &::zeitner::__private::Vector<36>,
        v: &::zeitner::__private::Vector<36>,
        t: ::zeitner::__private::Float,
    ) -> ::zeitner::__private::Matrix<35, 36> {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let s0 = 2.0 * (q[0] - q[2]);
        let s1 = 2.0 * (q[1] - q[3]);
        let s2 = 2.0 * (q[4] - q[6]);
        let s3 = 2.0 * (q[5] - q[7]);
        let s4 = 2.0 * (q[8] - q[10]);
        let s5 = 2.0 * (q[9] - q[11]);
        let s6 = 2.0 * (q[12] - q[14]);
        let s7 = 2.0 * (q[13] - q[15]);
        let s8 = 2.0 * (q[16] - q[18]);
        let s9 = 2.0 * (q[17] - q[19]);
        let s10 = 2.0 * (q[20] - q[22]);
        let s11 = 2.0 * (q[21] - q[23]);
        let s12 = 2.0 * (q[24] - q[26]);
        let s13 = 2.0 * (q[25] - q[27]);
        let s14 = 2.0 * (q[28] - q[30]);
        let s15 = 2.0 * (q[29] - q[31]);
        let s16 = 2.0 * (q[32] - q[34]);
        let s17 = 2.0 * (q[33] - q[35]);
        let s18 = 2.0 * (q[0] - q[4]);
        let s19 = 2.0 * (q[1] - q[5]);
        let s20 = 2.0 * (q[2] - q[6]);
        let s21 = 2.0 * (q[3] - q[7]);
        let s22 = 2.0 * (q[0] - q[6]);
        let s23 = 2.0 * (q[1] - q[7]);
        let s24 = 2.0 * (q[4] - q[8]);
        let s25 = 2.0 * (q[5] - q[9]);
        let s26 = 2.0 * (q[6] - q[10]);
        let s27 = 2.0 * (q[7] - q[11]);
        let s28 = 2.0 * (q[4] - q[10]);
        let s29 = 2.0 * (q[5] - q[11]);
        let s30 = 2.0 * (q[8] - q[12]);
        let s31 = 2.0 * (q[9] - q[13]);
        let s32 = 2.0 * (q[10] - q[14]);
        let s33 = 2.0 * (q[11] - q[15]);
        let s34 = 2.0 * (q[8] - q[14]);
        let s35 = 2.0 * (q[9] - q[15]);
        let s36 = 2.0 * (q[12] - q[16]);
        let s37 = 2.0 * (q[13] - q[17]);
        let s38 = 2.0 * (q[14] - q[18]);
        let s39 = 2.0 * (q[15] - q[19]);
        let s40 = 2.0 * (q[12] - q[18]);
        let s41 = 2.0 * (q[13] - q[19]);
        let s42 = 2.0 * (q[16] - q[20]);
        let s43 = 2.0 * (q[17] - q[21]);
        let s44 = 2.0 * (q[18] - q[22]);
        let s45 = 2.0 * (q[19] - q[23]);
        let s46 = 2.0 * (q[16] - q[22]);
        let s47 = 2.0 * (q[17] - q[23]);
        let s48 = 2.0 * (q[20] - q[24]);
        let s49 = 2.0 * (q[21] - q[25]);
        let s50 = 2.0 * (q[22] - q[26]);
        let s51 = 2.0 * (q[23] - q[27]);
        let s52 = 2.0 * (q[20] - q[26]);
        let s53 = 2.0 * (q[21] - q[27]);
        let s54 = 2.0 * (q[24] - q[28]);
        let s55 = 2.0 * (q[25] - q[29]);
        let s56 = 2.0 * (q[26] - q[30]);
        let s57 = 2.0 * (q[27] - q[31]);
        let s58 = 2.0 * (q[24] - q[30]);
        let s59 = 2.0 * (q[25] - q[31]);
        let s60 = 2.0 * (q[28] - q[32]);
        let s61 = 2.0 * (q[29] - q[33]);
        let s62 = 2.0 * (q[30] - q[34]);
        let s63 = 2.0 * (q[31] - q[35]);
        let s64 = 2.0 * (q[28] - q[34]);
        let s65 = 2.0 * (q[29] - q[35]);
        let mut g = ::zeitner::__private::Matrix::<35, 36>::zeros();
        g[(0, 0)] = s0;
        g[(0, 1)] = s1;
        g[(0, 2)] = -s0;
        g[(0, 3)] = -s1;
        g[(1, 4)] = s2;
        g[(1, 5)] = s3;
        g[(1, 6)] = -s2;
        g[(1, 7)] = -s3;
        g[(2, 8)] = s4;
        g[(2, 9)] = s5;
        g[(2, 10)] = -s4;
        g[(2, 11)] = -s5;
        g[(3, 12)] = s6;
        g[(3, 13)] = s7;
        g[(3, 14)] = -s6;
        g[(3, 15)] = -s7;
        g[(4, 16)] = s8;
        g[(4, 17)] = s9;
        g[(4, 18)] = -s8;
        g[(4, 19)] = -s9;
        g[(5, 20)] = s10;
        g[(5, 21)] = s11;
        g[(5, 22)] = -s10;
        g[(5, 23)] = -s11;
        g[(6, 24)] = s12;
        g[(6, 25)] = s13;
        g[(6, 26)] = -s12;
        g[(6, 27)] = -s13;
        g[(7, 28)] = s14;
        g[(7, 29)] = s15;
        g[(7, 30)] = -s14;
        g[(7, 31)] = -s15;
        g[(8, 32)] = s16;
        g[(8, 33)] = s17;
        g[(8, 34)] = -s16;
        g[(8, 35)] = -s17;
        g[(9, 0)] = s18;
        g[(9, 1)] = s19;
        g[(9, 4)] = -s18;
        g[(9, 5)] = -s19;
        g[(10, 2)] = s20;
        g[(10, 3)] = s21;
        g[(10, 6)] = -s20;
        g[(10, 7)] = -s21;
        g[(11, 0)] = s22;
        g[(11, 1)] = s23;
        g[(11, 6)] = -s22;
        g[(11, 7)] = -s23;
        g[(12, 4)] = s24;
        g[(12, 5)] = s25;
        g[(12, 8)] = -s24;
        g[(12, 9)] = -s25;
        g[(13, 6)] = s26;
        g[(13, 7)] = s27;
        g[(13, 10)] = -s26;
        g[(13, 11)] = -s27;
        g[(14, 4)] = s28;
        g[(14, 5)] = s29;
        g[(14, 10)] = -s28;
        g[(14, 11)] = -s29;
        g[(15, 8)] = s30;
        g[(15, 9)] = s31;
        g[(15, 12)] = -s30;
        g[(15, 13)] = -s31;
        g[(16, 10)] = s32;
        g[(16, 11)] = s33;
        g[(16, 14)] = -s32;
        g[(16, 15)] = -s33;
        g[(17, 8)] = s34;
        g[(17, 9)] = s35;
        g[(17, 14)] = -s34;
        g[(17, 15)] = -s35;
        g[(18, 12)] = s36;
        g[(18, 13)] = s37;
        g[(18, 16)] = -s36;
        g[(18, 17)] = -s37;
        g[(19, 14)] = s38;
        g[(19, 15)] = s39;
        g[(19, 18)] = -s38;
        g[(19, 19)] = -s39;
        g[(20, 12)] = s40;
        g[(20, 13)] = s41;
        g[(20, 18)] = -s40;
        g[(20, 19)] = -s41;
        g[(21, 16)] = s42;
        g[(21, 17)] = s43;
        g[(21, 20)] = -s42;
        g[(21, 21)] = -s43;
        g[(22, 18)] = s44;
        g[(22, 19)] = s45;
        g[(22, 22)] = -s44;
        g[(22, 23)] = -s45;
        g[(23, 16)] = s46;
        g[(23, 17)] = s47;
        g[(23, 22)] = -s46;
        g[(23, 23)] = -s47;
        g[(24, 20)] = s48;
        g[(24, 21)] = s49;
        g[(24, 24)] = -s48;
        g[(24, 25)] = -s49;
        g[(25, 22)] = s50;
        g[(25, 23)] = s51;
        g[(25, 26)] = -s50;
        g[(25, 27)] = -s51;
        g[(26, 20)] = s52;
        g[(26, 21)] = s53;
        g[(26, 26)] = -s52;
        g[(26, 27)] = -s53;
        g[(27, 24)] = s54;
        g[(27, 25)] = s55;
        g[(27, 28)] = -s54;
        g[(27, 29)] = -s55;
        g[(28, 26)] = s56;
        g[(28, 27)] = s57;
        g[(28, 30)] = -s56;
        g[(28, 31)] = -s57;
        g[(29, 24)] = s58;
        g[(29, 25)] = s59;
        g[(29, 30)] = -s58;
        g[(29, 31)] = -s59;
        g[(30, 28)] = s60;
        g[(30, 29)] = s61;
        g[(30, 32)] = -s60;
        g[(30, 33)] = -s61;
        g[(31, 30)] = s62;
        g[(31, 31)] = s63;
        g[(31, 34)] = -s62;
        g[(31, 35)] = -s63;
        g[(32, 28)] = s64;
        g[(32, 29)] = s65;
        g[(32, 34)] = -s64;
        g[(32, 35)] = -s65;
        g[(33, 0)] = 1.0;
        g[(34, 1)] = 1.0;
        g
    }
    #[inline]
    fn constraint_rate(
        &self,
        q: &::zeitner::__private::Vector<36>,
        v: &::zeitner::__private::Vector<36>,
        t: ::zeitner::__private::Float,
    ) -> ::zeitner::__private::Vector<35> {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let s0 = 2.0 * (q[0] - q[2]);
        let s1 = 2.0 * (q[1] - q[3]);
        let s2 = 2.0 * (q[4] - q[6]);
        let s3 = 2.0 * (q[5] - q[7]);
        let s4 = 2.0 * (q[8] - q[10]);
        let s5 = 2.0 * (q[9] - q[11]);
        let s6 = 2.0 * (q[12] - q[14]);
        let s7 = 2.0 * (q[13] - q[15]);
        let s8 = 2.0 * (q[16] - q[18]);
        let s9 = 2.0 * (q[17] - q[19]);
        let s10 = 2.0 * (q[20] - q[22]);
        let s11 = 2.0 * (q[21] - q[23]);
        let s12 = 2.0 * (q[24] - q[26]);
        let s13 = 2.0 * (q[25] - q[27]);
        let s14 = 2.0 * (q[28] - q[30]);
        let s15 = 2.0 * (q[29] - q[31]);
        let s16 = 2.0 * (q[32] - q[34]);
        let s17 = 2.0 * (q[33] - q[35]);
        let s18 = 2.0 * (q[0] - q[4]);
        let s19 = 2.0 * (q[1] - q[5]);
        let s20 = 2.0 * (q[2] - q[6]);
        let s21 = 2.0 * (q[3] - q[7]);
        let s22 = 2.0 * (q[0] - q[6]);
        let s23 = 2.0 * (q[1] - q[7]);
        let s24 = 2.0 * (q[4] - q[8]);
        let s25 = 2.0 * (q[5] - q[9]);
        let s26 = 2.0 * (q[6] - q[10]);
        let s27 = 2.0 * (q[7] - q[11]);
        let s28 = 2.0 * (q[4] - q[10]);
        let s29 = 2.0 * (q[5] - q[11]);
        let s30 = 2.0 * (q[8] - q[12]);
        let s31 = 2.0 * (q[9] - q[13]);
        let s32 = 2.0 * (q[10] - q[14]);
        let s33 = 2.0 * (q[11] - q[15]);
        let s34 = 2.0 * (q[8] - q[14]);
        let s35 = 2.0 * (q[9] - q[15]);
        let s36 = 2.0 * (q[12] - q[16]);
        let s37 = 2.0 * (q[13] - q[17]);
        let s38 = 2.0 * (q[14] - q[18]);
        let s39 = 2.0 * (q[15] - q[19]);
        let s40 = 2.0 * (q[12] - q[18]);
        let s41 = 2.0 * (q[13] - q[19]);
        let s42 = 2.0 * (q[16] - q[20]);
        let s43 = 2.0 * (q[17] - q[21]);
        let s44 = 2.0 * (q[18] - q[22]);
        let s45 = 2.0 * (q[19] - q[23]);
        let s46 = 2.0 * (q[16] - q[22]);
        let s47 = 2.0 * (q[17] - q[23]);
        let s48 = 2.0 * (q[20] - q[24]);
        let s49 = 2.0 * (q[21] - q[25]);
        let s50 = 2.0 * (q[22] - q[26]);
        let s51 = 2.0 * (q[23] - q[27]);
        let s52 = 2.0 * (q[20] - q[26]);
        let s53 = 2.0 * (q[21] - q[27]);
        let s54 = 2.0 * (q[24] - q[28]);
        let s55 = 2.0 * (q[25] - q[29]);
        let s56 = 2.0 * (q[26] - q[30]);
        let s57 = 2.0 * (q[27] - q[31]);
        let s58 = 2.0 * (q[24] - q[30]);
        let s59 = 2.0 * (q[25] - q[31]);
        let s60 = 2.0 * (q[28] - q[32]);
        let s61 = 2.0 * (q[29] - q[33]);
        let s62 = 2.0 * (q[30] - q[34]);
        let s63 = 2.0 * (q[31] - q[35]);
        let s64 = 2.0 * (q[28] - q[34]);
        let s65 = 2.0 * (q[29] - q[35]);
        let mut w = ::zeitner::__private::Vector::<35>::zeros();
        w[0] = s0 * v[0] + s1 * v[1] - s0 * v[2] - s1 * v[3];
        w[1] = s2 * v[4] + s3 * v[5] - s2 * v[6] - s3 * v[7];
        w[2] = s4 * v[8] + s5 * v[9] - s4 * v[10] - s5 * v[11];
        w[3] = s6 * v[12] + s7 * v[13] - s6 * v[14] - s7 * v[15];
        w[4] = s8 * v[16] + s9 * v[17] - s8 * v[18] - s9 * v[19];
        w[5] = s10 * v[20] + s11 * v[21] - s10 * v[22] - s11 * v[23];
        w[6] = s12 * v[24] + s13 * v[25] - s12 * v[26] - s13 * v[27];
        w[7] = s14 * v[28] + s15 * v[29] - s14 * v[30] - s15 * v[31];
        w[8] = s16 * v[32] + s17 * v[33] - s16 * v[34] - s17 * v[35];
        w[9] = s18 * v[0] + s19 * v[1] - s18 * v[4] - s19 * v[5];
        w[10] = s20 * v[2] + s21 * v[3] - s20 * v[6] - s21 * v[7];
        w[11] = s22 * v[0] + s23 * v[1] - s22 * v[6] - s23 * v[7];
        w[12] = s24 * v[4] + s25 * v[5] - s24 * v[8] - s25 * v[9];
        w[13] = s26 * v[6] + s27 * v[7] - s26 * v[10] - s27 * v[11];
        w[14] = s28 * v[4] + s29 * v[5] - s28 * v[10] - s29 * v[11];
        w[15] = s30 * v[8] + s31 * v[9] - s30 * v[12] - s31 * v[13];
        w[16] = s32 * v[10] + s33 * v[11] - s32 * v[14] - s33 * v[15];
        w[17] = s34 * v[8] + s35 * v[9] - s34 * v[14] - s35 * v[15];
        w[18] = s36 * v[12] + s37 * v[13] - s36 * v[16] - s37 * v[17];
        w[19] = s38 * v[14] + s39 * v[15] - s38 * v[18] - s39 * v[19];
        w[20] = s40 * v[12] + s41 * v[13] - s40 * v[18] - s41 * v[19];
        w[21] = s42 * v[16] + s43 * v[17] - s42 * v[20] - s43 * v[21];
        w[22] = s44 * v[18] + s45 * v[19] - s44 * v[22] - s45 * v[23];
        w[23] = s46 * v[16] + s47 * v[17] - s46 * v[22] - s47 * v[23];
        w[24] = s48 * v[20] + s49 * v[21] - s48 * v[24] - s49 * v[25];
        w[25] = s50 * v[22] + s51 * v[23] - s50 * v[26] - s51 * v[27];
        w[26] = s52 * v[20] + s53 * v[21] - s52 * v[26] - s53 * v[27];
        w[27] = s54 * v[24] + s55 * v[25] - s54 * v[28] - s55 * v[29];
        w[28] = s56 * v[26] + s57 * v[27] - s56 * v[30] - s57 * v[31];
        w[29] = s58 * v[24] + s59 * v[25] - s58 * v[30] - s59 * v[31];
        w[30] = s60 * v[28] + s61 * v[29] - s60 * v[32] - s61 * v[33];
        w[31] = s62 * v[30] + s63 * v[31] - s62 * v[34] - s63 * v[35];
        w[32] = s64 * v[28] + s65 * v[29] - s64 * v[34] - s65 * v[35];
        w[33] = v[0];
        w[34] = v[1];
        w
    }
    #[inline]
    fn constraint_acceleration_bias(
        &self,
        q: &::zeitner::__private::Vector<36>,
        v: &::zeitner::__private::Vector<36>,
        t: ::zeitner::__private::Float,
    ) -> ::zeitner::__private::Vector<35> {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let s0 = 2.0 * v[0];
        let s1 = 2.0 * v[2];
        let s2 = 2.0 * v[1];
        let s3 = 2.0 * v[3];
        let s4 = -2.0 * v[0];
        let s5 = -2.0 * v[2];
        let s6 = -2.0 * v[1];
        let s7 = -2.0 * v[3];
        let s8 = 2.0 * v[4];
        let s9 = 2.0 * v[6];
        let s10 = 2.0 * v[5];
        let s11 = 2.0 * v[7];
        let s12 = -2.0 * v[4];
        let s13 = -2.0 * v[6];
        let s14 = -2.0 * v[5];
        let s15 = -2.0 * v[7];
        let s16 = 2.0 * v[8];
        let s17 = 2.0 * v[10];
        let s18 = 2.0 * v[9];
        let s19 = 2.0 * v[11];
        let s20 = -2.0 * v[8];
        let s21 = -2.0 * v[10];
        let s22 = -2.0 * v[9];
        let s23 = -2.0 * v[11];
        let s24 = 2.0 * v[12];
        let s25 = 2.0 * v[14];
        let s26 = 2.0 * v[13];
        let s27 = 2.0 * v[15];
        let s28 = -2.0 * v[12];
        let s29 = -2.0 * v[14];
        let s30 = -2.0 * v[13];
        let s31 = -2.0 * v[15];
        let s32 = 2.0 * v[16];
        let s33 = 2.0 * v[18];
        let s34 = 2.0 * v[17];
        let s35 = 2.0 * v[19];
        let s36 = -2.0 * v[16];
        let s37 = -2.0 * v[18];
        let s38 = -2.0 * v[17];
        let s39 = -2.0 * v[19];
        let s40 = 2.0 * v[20];
        let s41 = 2.0 * v[22];
        let s42 = 2.0 * v[21];
        let s43 = 2.0 * v[23];
        let s44 = -2.0 * v[20];
        let s45 = -2.0 * v[22];
        let s46 = -2.0 * v[21];
        let s47 = -2.0 * v[23];
        let s48 = 2.0 * v[24];
        let s49 = 2.0 * v[26];
        let s50 = 2.0 * v[25];
        let s51 = 2.0 * v[27];
        let s52 = -2.0 * v[24];
        let s53 = -2.0 * v[26];
        let s54 = -2.0 * v[25];
        let s55 = -2.0 * v[27];
        let s56 = 2.0 * v[28];
        let s57 = 2.0 * v[30];
        let s58 = 2.0 * v[29];
        let s59 = 2.0 * v[31];
        let s60 = -2.0 * v[28];
        let s61 = -2.0 * v[30];
        let s62 = -2.0 * v[29];
        let s63 = -2.0 * v[31];
        let s64 = 2.0 * v[32];
        let s65 = 2.0 * v[34];
        let s66 = 2.0 * v[33];
        let s67 = 2.0 * v[35];
        let s68 = -2.0 * v[32];
        let s69 = -2.0 * v[34];
        let s70 = -2.0 * v[33];
        let s71 = -2.0 * v[35];
        let mut b = ::zeitner::__private::Vector::<35>::zeros();
        b[0] = v[0] * (s0 - s1) + v[1] * (s2 - s3) + v[2] * (s4 - s5) + v[3] * (s6 - s7);
        b[1] = v[4] * (s8 - s9) + v[5] * (s10 - s11) + v[6] * (s12 - s13)
            + v[7] * (s14 - s15);
        b[2] = v[8] * (s16 - s17) + v[9] * (s18 - s19) + v[10] * (s20 - s21)
            + v[11] * (s22 - s23);
        b[3] = v[12] * (s24 - s25) + v[13] * (s26 - s27) + v[14] * (s28 - s29)
            + v[15] * (s30 - s31);
        b[4] = v[16] * (s32 - s33) + v[17] * (s34 - s35) + v[18] * (s36 - s37)
            + v[19] * (s38 - s39);
        b[5] = v[20] * (s40 - s41) + v[21] * (s42 - s43) + v[22] * (s44 - s45)
            + v[23] * (s46 - s47);
        b[6] = v[24] * (s48 - s49) + v[25] * (s50 - s51) + v[26] * (s52 - s53)
            + v[27] * (s54 - s55);
        b[7] = v[28] * (s56 - s57) + v[29] * (s58 - s59) + v[30] * (s60 - s61)
            + v[31] * (s62 - s63);
        b[8] = v[32] * (s64 - s65) + v[33] * (s66 - s67) + v[34] * (s68 - s69)
            + v[35] * (s70 - s71);
        b[9] = v[0] * (s0 - s8) + v[1] * (s2 - s10) + v[4] * (s4 - s12)
            + v[5] * (s6 - s14);
        b[10] = v[2] * (s1 - s9) + v[3] * (s3 - s11) + v[6] * (s5 - s13)
            + v[7] * (s7 - s15);
        b[11] = v[0] * (s0 - s9) + v[1] * (s2 - s11) + v[6] * (s4 - s13)
            + v[7] * (s6 - s15);
        b[12] = v[4] * (s8 - s16) + v[5] * (s10 - s18) + v[8] * (s12 - s20)
            + v[9] * (s14 - s22);
        b[13] = v[6] * (s9 - s17) + v[7] * (s11 - s19) + v[10] * (s13 - s21)
            + v[11] * (s15 - s23);
        b[14] = v[4] * (s8 - s17) + v[5] * (s10 - s19) + v[10] * (s12 - s21)
            + v[11] * (s14 - s23);
        b[15] = v[8] * (s16 - s24) + v[9] * (s18 - s26) + v[12] * (s20 - s28)
            + v[13] * (s22 - s30);
        b[16] = v[10] * (s17 - s25) + v[11] * (s19 - s27) + v[14] * (s21 - s29)
            + v[15] * (s23 - s31);
        b[17] = v[8] * (s16 - s25) + v[9] * (s18 - s27) + v[14] * (s20 - s29)
            + v[15] * (s22 - s31);
        b[18] = v[12] * (s24 - s32) + v[13] * (s26 - s34) + v[16] * (s28 - s36)
            + v[17] * (s30 - s38);
        b[19] = v[14] * (s25 - s33) + v[15] * (s27 - s35) + v[18] * (s29 - s37)
            + v[19] * (s31 - s39);
        b[20] = v[12] * (s24 - s33) + v[13] * (s26 - s35) + v[18] * (s28 - s37)
            + v[19] * (s30 - s39);
        b[21] = v[16] * (s32 - s40) + v[17] * (s34 - s42) + v[20] * (s36 - s44)
            + v[21] * (s38 - s46);
        b[22] = v[18] * (s33 - s41) + v[19] * (s35 - s43) + v[22] * (s37 - s45)
            + v[23] * (s39 - s47);
        b[23] = v[16] * (s32 - s41) + v[17] * (s34 - s43) + v[22] * (s36 - s45)
            + v[23] * (s38 - s47);
        b[24] = v[20] * (s40 - s48) + v[21] * (s42 - s50) + v[24] * (s44 - s52)
            + v[25] * (s46 - s54);
        b[25] = v[22] * (s41 - s49) + v[23] * (s43 - s51) + v[26] * (s45 - s53)
            + v[27] * (s47 - s55);
        b[26] = v[20] * (s40 - s49) + v[21] * (s42 - s51) + v[26] * (s44 - s53)
            + v[27] * (s46 - s55);
        b[27] = v[24] * (s48 - s56) + v[25] * (s50 - s58) + v[28] * (s52 - s60)
            + v[29] * (s54 - s62);
        b[28] = v[26] * (s49 - s57) + v[27] * (s51 - s59) + v[30] * (s53 - s61)
            + v[31] * (s55 - s63);
        b[29] = v[24] * (s48 - s57) + v[25] * (s50 - s59) + v[30] * (s52 - s61)
            + v[31] * (s54 - s63);
        b[30] = v[28] * (s56 - s64) + v[29] * (s58 - s66) + v[32] * (s60 - s68)
            + v[33] * (s62 - s70);
        b[31] = v[30] * (s57 - s65) + v[31] * (s59 - s67) + v[34] * (s61 - s69)
            + v[35] * (s63 - s71);
        b[32] = v[28] * (s56 - s65) + v[29] * (s58 - s67) + v[34] * (s60 - s69)
            + v[35] * (s62 - s71);
        b
    }
    #[inline]
    fn stage(
        &self,
        q: &::zeitner::__private::Vector<36>,
        v: &::zeitner::__private::Vector<36>,
        t: ::zeitner::__private::Float,
    ) -> (
        Self::Mass,
        ::zeitner::__private::Vector<36>,
        ::zeitner::__private::Matrix<35, 36>,
        ::zeitner::__private::Vector<35>,
    ) {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let s0 = -(self.m * self.g);
        let s1 = 2.0 * (q[0] - q[2]);
        let s2 = 2.0 * (q[1] - q[3]);
        let s3 = 2.0 * (q[4] - q[6]);
        let s4 = 2.0 * (q[5] - q[7]);
        let s5 = 2.0 * (q[8] - q[10]);
        let s6 = 2.0 * (q[9] - q[11]);
        let s7 = 2.0 * (q[12] - q[14]);
        let s8 = 2.0 * (q[13] - q[15]);
        let s9 = 2.0 * (q[16] - q[18]);
        let s10 = 2.0 * (q[17] - q[19]);
        let s11 = 2.0 * (q[20] - q[22]);
        let s12 = 2.0 * (q[21] - q[23]);
        let s13 = 2.0 * (q[24] - q[26]);
        let s14 = 2.0 * (q[25] - q[27]);
        let s15 = 2.0 * (q[28] - q[30]);
        let s16 = 2.0 * (q[29] - q[31]);
        let s17 = 2.0 * (q[32] - q[34]);
        let s18 = 2.0 * (q[33] - q[35]);
        let s19 = 2.0 * (q[0] - q[4]);
        let s20 = 2.0 * (q[1] - q[5]);
        let s21 = 2.0 * (q[2] - q[6]);
        let s22 = 2.0 * (q[3] - q[7]);
        let s23 = 2.0 * (q[0] - q[6]);
        let s24 = 2.0 * (q[1] - q[7]);
        let s25 = 2.0 * (q[4] - q[8]);
        let s26 = 2.0 * (q[5] - q[9]);
        let s27 = 2.0 * (q[6] - q[10]);
        let s28 = 2.0 * (q[7] - q[11]);
        let s29 = 2.0 * (q[4] - q[10]);
        let s30 = 2.0 * (q[5] - q[11]);
        let s31 = 2.0 * (q[8] - q[12]);
        let s32 = 2.0 * (q[9] - q[13]);
        let s33 = 2.0 * (q[10] - q[14]);
        let s34 = 2.0 * (q[11] - q[15]);
        let s35 = 2.0 * (q[8] - q[14]);
        let s36 = 2.0 * (q[9] - q[15]);
        let s37 = 2.0 * (q[12] - q[16]);
        let s38 = 2.0 * (q[13] - q[17]);
        let s39 = 2.0 * (q[14] - q[18]);
        let s40 = 2.0 * (q[15] - q[19]);
        let s41 = 2.0 * (q[12] - q[18]);
        let s42 = 2.0 * (q[13] - q[19]);
        let s43 = 2.0 * (q[16] - q[20]);
        let s44 = 2.0 * (q[17] - q[21]);
        let s45 = 2.0 * (q[18] - q[22]);
        let s46 = 2.0 * (q[19] - q[23]);
        let s47 = 2.0 * (q[16] - q[22]);
        let s48 = 2.0 * (q[17] - q[23]);
        let s49 = 2.0 * (q[20] - q[24]);
        let s50 = 2.0 * (q[21] - q[25]);
        let s51 = 2.0 * (q[22] - q[26]);
        let s52 = 2.0 * (q[23] - q[27]);
        let s53 = 2.0 * (q[20] - q[26]);
        let s54 = 2.0 * (q[21] - q[27]);
        let s55 = 2.0 * (q[24] - q[28]);
        let s56 = 2.0 * (q[25] - q[29]);
        let s57 = 2.0 * (q[26] - q[30]);
        let s58 = 2.0 * (q[27] - q[31]);
        let s59 = 2.0 * (q[24] - q[30]);
        let s60 = 2.0 * (q[25] - q[31]);
        let s61 = 2.0 * (q[28] - q[32]);
        let s62 = 2.0 * (q[29] - q[33]);
        let s63 = 2.0 * (q[30] - q[34]);
        let s64 = 2.0 * (q[31] - q[35]);
        let s65 = 2.0 * (q[28] - q[34]);
        let s66 = 2.0 * (q[29] - q[35]);
        let s67 = 2.0 * v[0];
        let s68 = 2.0 * v[2];
        let s69 = 2.0 * v[1];
        let s70 = 2.0 * v[3];
        let s71 = -2.0 * v[0];
        let s72 = -2.0 * v[2];
        let s73 = -2.0 * v[1];
        let s74 = -2.0 * v[3];
        let s75 = 2.0 * v[4];
        let s76 = 2.0 * v[6];
        let s77 = 2.0 * v[5];
        let s78 = 2.0 * v[7];
        let s79 = -2.0 * v[4];
        let s80 = -2.0 * v[6];
        let s81 = -2.0 * v[5];
        let s82 = -2.0 * v[7];
        let s83 = 2.0 * v[8];
        let s84 = 2.0 * v[10];
        let s85 = 2.0 * v[9];
        let s86 = 2.0 * v[11];
        let s87 = -2.0 * v[8];
        let s88 = -2.0 * v[10];
        let s89 = -2.0 * v[9];
        let s90 = -2.0 * v[11];
        let s91 = 2.0 * v[12];
        let s92 = 2.0 * v[14];
        let s93 = 2.0 * v[13];
        let s94 = 2.0 * v[15];
        let s95 = -2.0 * v[12];
        let s96 = -2.0 * v[14];
        let s97 = -2.0 * v[13];
        let s98 = -2.0 * v[15];
        let s99 = 2.0 * v[16];
        let s100 = 2.0 * v[18];
        let s101 = 2.0 * v[17];
        let s102 = 2.0 * v[19];
        let s103 = -2.0 * v[16];
        let s104 = -2.0 * v[18];
        let s105 = -2.0 * v[17];
        let s106 = -2.0 * v[19];
        let s107 = 2.0 * v[20];
        let s108 = 2.0 * v[22];
        let s109 = 2.0 * v[21];
        let s110 = 2.0 * v[23];
        let s111 = -2.0 * v[20];
        let s112 = -2.0 * v[22];
        let s113 = -2.0 * v[21];
        let s114 = -2.0 * v[23];
        let s115 = 2.0 * v[24];
        let s116 = 2.0 * v[26];
        let s117 = 2.0 * v[25];
        let s118 = 2.0 * v[27];
        let s119 = -2.0 * v[24];
        let s120 = -2.0 * v[26];
        let s121 = -2.0 * v[25];
        let s122 = -2.0 * v[27];
        let s123 = 2.0 * v[28];
        let s124 = 2.0 * v[30];
        let s125 = 2.0 * v[29];
        let s126 = 2.0 * v[31];
        let s127 = -2.0 * v[28];
        let s128 = -2.0 * v[30];
        let s129 = -2.0 * v[29];
        let s130 = -2.0 * v[31];
        let s131 = 2.0 * v[32];
        let s132 = 2.0 * v[34];
        let s133 = 2.0 * v[33];
        let s134 = 2.0 * v[35];
        let s135 = -2.0 * v[32];
        let s136 = -2.0 * v[34];
        let s137 = -2.0 * v[33];
        let s138 = -2.0 * v[35];
        let mut m = ::zeitner::__private::Vector::<36>::zeros();
        let mut f = ::zeitner::__private::Vector::<36>::zeros();
        let mut g = ::zeitner::__private::Matrix::<35, 36>::zeros();
        let mut b = ::zeitner::__private::Vector::<35>::zeros();
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
        g[(0, 0)] = s1;
        g[(0, 1)] = s2;
        g[(0, 2)] = -s1;
        g[(0, 3)] = -s2;
        g[(1, 4)] = s3;
        g[(1, 5)] = s4;
        g[(1, 6)] = -s3;
        g[(1, 7)] = -s4;
        g[(2, 8)] = s5;
        g[(2, 9)] = s6;
        g[(2, 10)] = -s5;
        g[(2, 11)] = -s6;
        g[(3, 12)] = s7;
        g[(3, 13)] = s8;
        g[(3, 14)] = -s7;
        g[(3, 15)] = -s8;
        g[(4, 16)] = s9;
        g[(4, 17)] = s10;
        g[(4, 18)] = -s9;
        g[(4, 19)] = -s10;
        g[(5, 20)] = s11;
        g[(5, 21)] = s12;
        g[(5, 22)] = -s11;
        g[(5, 23)] = -s12;
        g[(6, 24)] = s13;
        g[(6, 25)] = s14;
        g[(6, 26)] = -s13;
        g[(6, 27)] = -s14;
        g[(7, 28)] = s15;
        g[(7, 29)] = s16;
        g[(7, 30)] = -s15;
        g[(7, 31)] = -s16;
        g[(8, 32)] = s17;
        g[(8, 33)] = s18;
        g[(8, 34)] = -s17;
        g[(8, 35)] = -s18;
        g[(9, 0)] = s19;
        g[(9, 1)] = s20;
        g[(9, 4)] = -s19;
        g[(9, 5)] = -s20;
        g[(10, 2)] = s21;
        g[(10, 3)] = s22;
        g[(10, 6)] = -s21;
        g[(10, 7)] = -s22;
        g[(11, 0)] = s23;
        g[(11, 1)] = s24;
        g[(11, 6)] = -s23;
        g[(11, 7)] = -s24;
        g[(12, 4)] = s25;
        g[(12, 5)] = s26;
        g[(12, 8)] = -s25;
        g[(12, 9)] = -s26;
        g[(13, 6)] = s27;
        g[(13, 7)] = s28;
        g[(13, 10)] = -s27;
        g[(13, 11)] = -s28;
        g[(14, 4)] = s29;
        g[(14, 5)] = s30;
        g[(14, 10)] = -s29;
        g[(14, 11)] = -s30;
        g[(15, 8)] = s31;
        g[(15, 9)] = s32;
        g[(15, 12)] = -s31;
        g[(15, 13)] = -s32;
        g[(16, 10)] = s33;
        g[(16, 11)] = s34;
        g[(16, 14)] = -s33;
        g[(16, 15)] = -s34;
        g[(17, 8)] = s35;
        g[(17, 9)] = s36;
        g[(17, 14)] = -s35;
        g[(17, 15)] = -s36;
        g[(18, 12)] = s37;
        g[(18, 13)] = s38;
        g[(18, 16)] = -s37;
        g[(18, 17)] = -s38;
        g[(19, 14)] = s39;
        g[(19, 15)] = s40;
        g[(19, 18)] = -s39;
        g[(19, 19)] = -s40;
        g[(20, 12)] = s41;
        g[(20, 13)] = s42;
        g[(20, 18)] = -s41;
        g[(20, 19)] = -s42;
        g[(21, 16)] = s43;
        g[(21, 17)] = s44;
        g[(21, 20)] = -s43;
        g[(21, 21)] = -s44;
        g[(22, 18)] = s45;
        g[(22, 19)] = s46;
        g[(22, 22)] = -s45;
        g[(22, 23)] = -s46;
        g[(23, 16)] = s47;
        g[(23, 17)] = s48;
        g[(23, 22)] = -s47;
        g[(23, 23)] = -s48;
        g[(24, 20)] = s49;
        g[(24, 21)] = s50;
        g[(24, 24)] = -s49;
        g[(24, 25)] = -s50;
        g[(25, 22)] = s51;
        g[(25, 23)] = s52;
        g[(25, 26)] = -s51;
        g[(25, 27)] = -s52;
        g[(26, 20)] = s53;
        g[(26, 21)] = s54;
        g[(26, 26)] = -s53;
        g[(26, 27)] = -s54;
        g[(27, 24)] = s55;
        g[(27, 25)] = s56;
        g[(27, 28)] = -s55;
        g[(27, 29)] = -s56;
        g[(28, 26)] = s57;
        g[(28, 27)] = s58;
        g[(28, 30)] = -s57;
        g[(28, 31)] = -s58;
        g[(29, 24)] = s59;
        g[(29, 25)] = s60;
        g[(29, 30)] = -s59;
        g[(29, 31)] = -s60;
        g[(30, 28)] = s61;
        g[(30, 29)] = s62;
        g[(30, 32)] = -s61;
        g[(30, 33)] = -s62;
        g[(31, 30)] = s63;
        g[(31, 31)] = s64;
        g[(31, 34)] = -s63;
        g[(31, 35)] = -s64;
        g[(32, 28)] = s65;
        g[(32, 29)] = s66;
        g[(32, 34)] = -s65;
        g[(32, 35)] = -s66;
        g[(33, 0)] = 1.0;
        g[(34, 1)] = 1.0;
        b[0] = v[0] * (s67 - s68) + v[1] * (s69 - s70) + v[2] * (s71 - s72)
            + v[3] * (s73 - s74);
        b[1] = v[4] * (s75 - s76) + v[5] * (s77 - s78) + v[6] * (s79 - s80)
            + v[7] * (s81 - s82);
        b[2] = v[8] * (s83 - s84) + v[9] * (s85 - s86) + v[10] * (s87 - s88)
            + v[11] * (s89 - s90);
        b[3] = v[12] * (s91 - s92) + v[13] * (s93 - s94) + v[14] * (s95 - s96)
            + v[15] * (s97 - s98);
        b[4] = v[16] * (s99 - s100) + v[17] * (s101 - s102) + v[18] * (s103 - s104)
            + v[19] * (s105 - s106);
        b[5] = v[20] * (s107 - s108) + v[21] * (s109 - s110) + v[22] * (s111 - s112)
            + v[23] * (s113 - s114);
        b[6] = v[24] * (s115 - s116) + v[25] * (s117 - s118) + v[26] * (s119 - s120)
            + v[27] * (s121 - s122);
        b[7] = v[28] * (s123 - s124) + v[29] * (s125 - s126) + v[30] * (s127 - s128)
            + v[31] * (s129 - s130);
        b[8] = v[32] * (s131 - s132) + v[33] * (s133 - s134) + v[34] * (s135 - s136)
            + v[35] * (s137 - s138);
        b[9] = v[0] * (s67 - s75) + v[1] * (s69 - s77) + v[4] * (s71 - s79)
            + v[5] * (s73 - s81);
        b[10] = v[2] * (s68 - s76) + v[3] * (s70 - s78) + v[6] * (s72 - s80)
            + v[7] * (s74 - s82);
        b[11] = v[0] * (s67 - s76) + v[1] * (s69 - s78) + v[6] * (s71 - s80)
            + v[7] * (s73 - s82);
        b[12] = v[4] * (s75 - s83) + v[5] * (s77 - s85) + v[8] * (s79 - s87)
            + v[9] * (s81 - s89);
        b[13] = v[6] * (s76 - s84) + v[7] * (s78 - s86) + v[10] * (s80 - s88)
            + v[11] * (s82 - s90);
        b[14] = v[4] * (s75 - s84) + v[5] * (s77 - s86) + v[10] * (s79 - s88)
            + v[11] * (s81 - s90);
        b[15] = v[8] * (s83 - s91) + v[9] * (s85 - s93) + v[12] * (s87 - s95)
            + v[13] * (s89 - s97);
        b[16] = v[10] * (s84 - s92) + v[11] * (s86 - s94) + v[14] * (s88 - s96)
            + v[15] * (s90 - s98);
        b[17] = v[8] * (s83 - s92) + v[9] * (s85 - s94) + v[14] * (s87 - s96)
            + v[15] * (s89 - s98);
        b[18] = v[12] * (s91 - s99) + v[13] * (s93 - s101) + v[16] * (s95 - s103)
            + v[17] * (s97 - s105);
        b[19] = v[14] * (s92 - s100) + v[15] * (s94 - s102) + v[18] * (s96 - s104)
            + v[19] * (s98 - s106);
        b[20] = v[12] * (s91 - s100) + v[13] * (s93 - s102) + v[18] * (s95 - s104)
            + v[19] * (s97 - s106);
        b[21] = v[16] * (s99 - s107) + v[17] * (s101 - s109) + v[20] * (s103 - s111)
            + v[21] * (s105 - s113);
        b[22] = v[18] * (s100 - s108) + v[19] * (s102 - s110) + v[22] * (s104 - s112)
            + v[23] * (s106 - s114);
        b[23] = v[16] * (s99 - s108) + v[17] * (s101 - s110) + v[22] * (s103 - s112)
            + v[23] * (s105 - s114);
        b[24] = v[20] * (s107 - s115) + v[21] * (s109 - s117) + v[24] * (s111 - s119)
            + v[25] * (s113 - s121);
        b[25] = v[22] * (s108 - s116) + v[23] * (s110 - s118) + v[26] * (s112 - s120)
            + v[27] * (s114 - s122);
        b[26] = v[20] * (s107 - s116) + v[21] * (s109 - s118) + v[26] * (s111 - s120)
            + v[27] * (s113 - s122);
        b[27] = v[24] * (s115 - s123) + v[25] * (s117 - s125) + v[28] * (s119 - s127)
            + v[29] * (s121 - s129);
        b[28] = v[26] * (s116 - s124) + v[27] * (s118 - s126) + v[30] * (s120 - s128)
            + v[31] * (s122 - s130);
        b[29] = v[24] * (s115 - s124) + v[25] * (s117 - s126) + v[30] * (s119 - s128)
            + v[31] * (s121 - s130);
        b[30] = v[28] * (s123 - s131) + v[29] * (s125 - s133) + v[32] * (s127 - s135)
            + v[33] * (s129 - s137);
        b[31] = v[30] * (s124 - s132) + v[31] * (s126 - s134) + v[34] * (s128 - s136)
            + v[35] * (s130 - s138);
        b[32] = v[28] * (s123 - s132) + v[29] * (s125 - s134) + v[34] * (s127 - s136)
            + v[35] * (s129 - s138);
        (::zeitner::__private::DiagonalMass(m), f, g, b)
    }
    #[inline]
    fn force_jacobians(
        &self,
        q: &::zeitner::__private::Vector<36>,
        v: &::zeitner::__private::Vector<36>,
        t: ::zeitner::__private::Float,
    ) -> (::zeitner::__private::Matrix<36, 36>, ::zeitner::__private::Matrix<36, 36>) {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let mut dq = ::zeitner::__private::Matrix::<36, 36>::zeros();
        let mut dv = ::zeitner::__private::Matrix::<36, 36>::zeros();
        (dq, dv)
    }
    #[inline]
    fn constraint_force_jacobians(
        &self,
        q: &::zeitner::__private::Vector<36>,
        v: &::zeitner::__private::Vector<36>,
        t: ::zeitner::__private::Float,
        lambda: &::zeitner::__private::Vector<35>,
    ) -> (::zeitner::__private::Matrix<36, 36>, ::zeitner::__private::Matrix<36, 36>) {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let s0 = 2.0 * lambda[0];
        let s1 = 2.0 * lambda[9];
        let s2 = 2.0 * lambda[11];
        let s3 = s0 + s1 + s2;
        let s4 = -2.0 * lambda[0];
        let s5 = -2.0 * lambda[9];
        let s6 = -2.0 * lambda[11];
        let s7 = -s0;
        let s8 = 2.0 * lambda[10];
        let s9 = s8 - s4;
        let s10 = -2.0 * lambda[10];
        let s11 = -s1;
        let s12 = 2.0 * lambda[1];
        let s13 = 2.0 * lambda[12];
        let s14 = 2.0 * lambda[14];
        let s15 = s12 - s5 + s13 + s14;
        let s16 = -2.0 * lambda[1];
        let s17 = -2.0 * lambda[12];
        let s18 = -2.0 * lambda[14];
        let s19 = -s2;
        let s20 = -s8;
        let s21 = -s12;
        let s22 = 2.0 * lambda[13];
        let s23 = -s16 - s10 - s6 + s22;
        let s24 = -2.0 * lambda[13];
        let s25 = -s13;
        let s26 = 2.0 * lambda[2];
        let s27 = 2.0 * lambda[15];
        let s28 = 2.0 * lambda[17];
        let s29 = s26 - s17 + s27 + s28;
        let s30 = -2.0 * lambda[2];
        let s31 = -2.0 * lambda[15];
        let s32 = -2.0 * lambda[17];
        let s33 = -s14;
        let s34 = -s22;
        let s35 = -s26;
        let s36 = 2.0 * lambda[16];
        let s37 = -s30 - s24 - s18 + s36;
        let s38 = -2.0 * lambda[16];
        let s39 = -s27;
        let s40 = 2.0 * lambda[3];
        let s41 = 2.0 * lambda[18];
        let s42 = 2.0 * lambda[20];
        let s43 = s40 - s31 + s41 + s42;
        let s44 = -2.0 * lambda[3];
        let s45 = -2.0 * lambda[18];
        let s46 = -2.0 * lambda[20];
        let s47 = -s28;
        let s48 = -s36;
        let s49 = -s40;
        let s50 = 2.0 * lambda[19];
        let s51 = -s44 - s38 - s32 + s50;
        let s52 = -2.0 * lambda[19];
        let s53 = -s41;
        let s54 = 2.0 * lambda[4];
        let s55 = 2.0 * lambda[21];
        let s56 = 2.0 * lambda[23];
        let s57 = s54 - s45 + s55 + s56;
        let s58 = -2.0 * lambda[4];
        let s59 = -2.0 * lambda[21];
        let s60 = -2.0 * lambda[23];
        let s61 = -s42;
        let s62 = -s50;
        let s63 = -s54;
        let s64 = 2.0 * lambda[22];
        let s65 = -s58 - s52 - s46 + s64;
        let s66 = -2.0 * lambda[22];
        let s67 = -s55;
        let s68 = 2.0 * lambda[5];
        let s69 = 2.0 * lambda[24];
        let s70 = 2.0 * lambda[26];
        let s71 = s68 - s59 + s69 + s70;
        let s72 = -2.0 * lambda[5];
        let s73 = -2.0 * lambda[24];
        let s74 = -2.0 * lambda[26];
        let s75 = -s56;
        let s76 = -s64;
        let s77 = -s68;
        let s78 = 2.0 * lambda[25];
        let s79 = -s72 - s66 - s60 + s78;
        let s80 = -2.0 * lambda[25];
        let s81 = -s69;
        let s82 = 2.0 * lambda[6];
        let s83 = 2.0 * lambda[27];
        let s84 = 2.0 * lambda[29];
        let s85 = s82 - s73 + s83 + s84;
        let s86 = -2.0 * lambda[6];
        let s87 = -2.0 * lambda[27];
        let s88 = -2.0 * lambda[29];
        let s89 = -s70;
        let s90 = -s78;
        let s91 = -s82;
        let s92 = 2.0 * lambda[28];
        let s93 = -s86 - s80 - s74 + s92;
        let s94 = -2.0 * lambda[28];
        let s95 = -s83;
        let s96 = 2.0 * lambda[7];
        let s97 = 2.0 * lambda[30];
        let s98 = 2.0 * lambda[32];
        let s99 = s96 - s87 + s97 + s98;
        let s100 = -2.0 * lambda[7];
        let s101 = -2.0 * lambda[30];
        let s102 = -2.0 * lambda[32];
        let s103 = -s84;
        let s104 = -s92;
        let s105 = -s96;
        let s106 = 2.0 * lambda[31];
        let s107 = -s100 - s94 - s88 + s106;
        let s108 = -2.0 * lambda[31];
        let s109 = -s97;
        let s110 = 2.0 * lambda[8];
        let s111 = s110 - s101;
        let s112 = -2.0 * lambda[8];
        let s113 = -s98;
        let s114 = -s106;
        let s115 = -s110;
        let s116 = -s112 - s108 - s102;
        let mut dq = ::zeitner::__private::Matrix::<36, 36>::zeros();
        let mut dv = ::zeitner::__private::Matrix::<36, 36>::zeros();
        dq[(0, 0)] = s3;
        dq[(0, 2)] = s4;
        dq[(0, 4)] = s5;
        dq[(0, 6)] = s6;
        dq[(1, 1)] = s3;
        dq[(1, 3)] = s4;
        dq[(1, 5)] = s5;
        dq[(1, 7)] = s6;
        dq[(2, 0)] = s7;
        dq[(2, 2)] = s9;
        dq[(2, 6)] = s10;
        dq[(3, 1)] = s7;
        dq[(3, 3)] = s9;
        dq[(3, 7)] = s10;
        dq[(4, 0)] = s11;
        dq[(4, 4)] = s15;
        dq[(4, 6)] = s16;
        dq[(4, 8)] = s17;
        dq[(4, 10)] = s18;
        dq[(5, 1)] = s11;
        dq[(5, 5)] = s15;
        dq[(5, 7)] = s16;
        dq[(5, 9)] = s17;
        dq[(5, 11)] = s18;
        dq[(6, 0)] = s19;
        dq[(6, 2)] = s20;
        dq[(6, 4)] = s21;
        dq[(6, 6)] = s23;
        dq[(6, 10)] = s24;
        dq[(7, 1)] = s19;
        dq[(7, 3)] = s20;
        dq[(7, 5)] = s21;
        dq[(7, 7)] = s23;
        dq[(7, 11)] = s24;
        dq[(8, 4)] = s25;
        dq[(8, 8)] = s29;
        dq[(8, 10)] = s30;
        dq[(8, 12)] = s31;
        dq[(8, 14)] = s32;
        dq[(9, 5)] = s25;
        dq[(9, 9)] = s29;
        dq[(9, 11)] = s30;
        dq[(9, 13)] = s31;
        dq[(9, 15)] = s32;
        dq[(10, 4)] = s33;
        dq[(10, 6)] = s34;
        dq[(10, 8)] = s35;
        dq[(10, 10)] = s37;
        dq[(10, 14)] = s38;
        dq[(11, 5)] = s33;
        dq[(11, 7)] = s34;
        dq[(11, 9)] = s35;
        dq[(11, 11)] = s37;
        dq[(11, 15)] = s38;
        dq[(12, 8)] = s39;
        dq[(12, 12)] = s43;
        dq[(12, 14)] = s44;
        dq[(12, 16)] = s45;
        dq[(12, 18)] = s46;
        dq[(13, 9)] = s39;
        dq[(13, 13)] = s43;
        dq[(13, 15)] = s44;
        dq[(13, 17)] = s45;
        dq[(13, 19)] = s46;
        dq[(14, 8)] = s47;
        dq[(14, 10)] = s48;
        dq[(14, 12)] = s49;
        dq[(14, 14)] = s51;
        dq[(14, 18)] = s52;
        dq[(15, 9)] = s47;
        dq[(15, 11)] = s48;
        dq[(15, 13)] = s49;
        dq[(15, 15)] = s51;
        dq[(15, 19)] = s52;
        dq[(16, 12)] = s53;
        dq[(16, 16)] = s57;
        dq[(16, 18)] = s58;
        dq[(16, 20)] = s59;
        dq[(16, 22)] = s60;
        dq[(17, 13)] = s53;
        dq[(17, 17)] = s57;
        dq[(17, 19)] = s58;
        dq[(17, 21)] = s59;
        dq[(17, 23)] = s60;
        dq[(18, 12)] = s61;
        dq[(18, 14)] = s62;
        dq[(18, 16)] = s63;
        dq[(18, 18)] = s65;
        dq[(18, 22)] = s66;
        dq[(19, 13)] = s61;
        dq[(19, 15)] = s62;
        dq[(19, 17)] = s63;
        dq[(19, 19)] = s65;
        dq[(19, 23)] = s66;
        dq[(20, 16)] = s67;
        dq[(20, 20)] = s71;
        dq[(20, 22)] = s72;
        dq[(20, 24)] = s73;
        dq[(20, 26)] = s74;
        dq[(21, 17)] = s67;
        dq[(21, 21)] = s71;
        dq[(21, 23)] = s72;
        dq[(21, 25)] = s73;
        dq[(21, 27)] = s74;
        dq[(22, 16)] = s75;
        dq[(22, 18)] = s76;
        dq[(22, 20)] = s77;
        dq[(22, 22)] = s79;
        dq[(22, 26)] = s80;
        dq[(23, 17)] = s75;
        dq[(23, 19)] = s76;
        dq[(23, 21)] = s77;
        dq[(23, 23)] = s79;
        dq[(23, 27)] = s80;
        dq[(24, 20)] = s81;
        dq[(24, 24)] = s85;
        dq[(24, 26)] = s86;
        dq[(24, 28)] = s87;
        dq[(24, 30)] = s88;
        dq[(25, 21)] = s81;
        dq[(25, 25)] = s85;
        dq[(25, 27)] = s86;
        dq[(25, 29)] = s87;
        dq[(25, 31)] = s88;
        dq[(26, 20)] = s89;
        dq[(26, 22)] = s90;
        dq[(26, 24)] = s91;
        dq[(26, 26)] = s93;
        dq[(26, 30)] = s94;
        dq[(27, 21)] = s89;
        dq[(27, 23)] = s90;
        dq[(27, 25)] = s91;
        dq[(27, 27)] = s93;
        dq[(27, 31)] = s94;
        dq[(28, 24)] = s95;
        dq[(28, 28)] = s99;
        dq[(28, 30)] = s100;
        dq[(28, 32)] = s101;
        dq[(28, 34)] = s102;
        dq[(29, 25)] = s95;
        dq[(29, 29)] = s99;
        dq[(29, 31)] = s100;
        dq[(29, 33)] = s101;
        dq[(29, 35)] = s102;
        dq[(30, 24)] = s103;
        dq[(30, 26)] = s104;
        dq[(30, 28)] = s105;
        dq[(30, 30)] = s107;
        dq[(30, 34)] = s108;
        dq[(31, 25)] = s103;
        dq[(31, 27)] = s104;
        dq[(31, 29)] = s105;
        dq[(31, 31)] = s107;
        dq[(31, 35)] = s108;
        dq[(32, 28)] = s109;
        dq[(32, 32)] = s111;
        dq[(32, 34)] = s112;
        dq[(33, 29)] = s109;
        dq[(33, 33)] = s111;
        dq[(33, 35)] = s112;
        dq[(34, 28)] = s113;
        dq[(34, 30)] = s114;
        dq[(34, 32)] = s115;
        dq[(34, 34)] = s116;
        dq[(35, 29)] = s113;
        dq[(35, 31)] = s114;
        dq[(35, 33)] = s115;
        dq[(35, 35)] = s116;
        (dq, dv)
    }
    #[inline]
    fn constraint_jacobian_nonzeros(
        &self,
        q: &::zeitner::__private::Vector<36>,
        v: &::zeitner::__private::Vector<36>,
        t: ::zeitner::__private::Float,
        values: &mut [::zeitner::__private::Float],
    ) {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let s0 = 2.0 * (q[0] - q[2]);
        let s1 = 2.0 * (q[1] - q[3]);
        let s2 = 2.0 * (q[4] - q[6]);
        let s3 = 2.0 * (q[5] - q[7]);
        let s4 = 2.0 * (q[8] - q[10]);
        let s5 = 2.0 * (q[9] - q[11]);
        let s6 = 2.0 * (q[12] - q[14]);
        let s7 = 2.0 * (q[13] - q[15]);
        let s8 = 2.0 * (q[16] - q[18]);
        let s9 = 2.0 * (q[17] - q[19]);
        let s10 = 2.0 * (q[20] - q[22]);
        let s11 = 2.0 * (q[21] - q[23]);
        let s12 = 2.0 * (q[24] - q[26]);
        let s13 = 2.0 * (q[25] - q[27]);
        let s14 = 2.0 * (q[28] - q[30]);
        let s15 = 2.0 * (q[29] - q[31]);
        let s16 = 2.0 * (q[32] - q[34]);
        let s17 = 2.0 * (q[33] - q[35]);
        let s18 = 2.0 * (q[0] - q[4]);
        let s19 = 2.0 * (q[1] - q[5]);
        let s20 = 2.0 * (q[2] - q[6]);
        let s21 = 2.0 * (q[3] - q[7]);
        let s22 = 2.0 * (q[0] - q[6]);
        let s23 = 2.0 * (q[1] - q[7]);
        let s24 = 2.0 * (q[4] - q[8]);
        let s25 = 2.0 * (q[5] - q[9]);
        let s26 = 2.0 * (q[6] - q[10]);
        let s27 = 2.0 * (q[7] - q[11]);
        let s28 = 2.0 * (q[4] - q[10]);
        let s29 = 2.0 * (q[5] - q[11]);
        let s30 = 2.0 * (q[8] - q[12]);
        let s31 = 2.0 * (q[9] - q[13]);
        let s32 = 2.0 * (q[10] - q[14]);
        let s33 = 2.0 * (q[11] - q[15]);
        let s34 = 2.0 * (q[8] - q[14]);
        let s35 = 2.0 * (q[9] - q[15]);
        let s36 = 2.0 * (q[12] - q[16]);
        let s37 = 2.0 * (q[13] - q[17]);
        let s38 = 2.0 * (q[14] - q[18]);
        let s39 = 2.0 * (q[15] - q[19]);
        let s40 = 2.0 * (q[12] - q[18]);
        let s41 = 2.0 * (q[13] - q[19]);
        let s42 = 2.0 * (q[16] - q[20]);
        let s43 = 2.0 * (q[17] - q[21]);
        let s44 = 2.0 * (q[18] - q[22]);
        let s45 = 2.0 * (q[19] - q[23]);
        let s46 = 2.0 * (q[16] - q[22]);
        let s47 = 2.0 * (q[17] - q[23]);
        let s48 = 2.0 * (q[20] - q[24]);
        let s49 = 2.0 * (q[21] - q[25]);
        let s50 = 2.0 * (q[22] - q[26]);
        let s51 = 2.0 * (q[23] - q[27]);
        let s52 = 2.0 * (q[20] - q[26]);
        let s53 = 2.0 * (q[21] - q[27]);
        let s54 = 2.0 * (q[24] - q[28]);
        let s55 = 2.0 * (q[25] - q[29]);
        let s56 = 2.0 * (q[26] - q[30]);
        let s57 = 2.0 * (q[27] - q[31]);
        let s58 = 2.0 * (q[24] - q[30]);
        let s59 = 2.0 * (q[25] - q[31]);
        let s60 = 2.0 * (q[28] - q[32]);
        let s61 = 2.0 * (q[29] - q[33]);
        let s62 = 2.0 * (q[30] - q[34]);
        let s63 = 2.0 * (q[31] - q[35]);
        let s64 = 2.0 * (q[28] - q[34]);
        let s65 = 2.0 * (q[29] - q[35]);
        values[0] = s0;
        values[1] = s1;
        values[2] = -s0;
        values[3] = -s1;
        values[4] = s2;
        values[5] = s3;
        values[6] = -s2;
        values[7] = -s3;
        values[8] = s4;
        values[9] = s5;
        values[10] = -s4;
        values[11] = -s5;
        values[12] = s6;
        values[13] = s7;
        values[14] = -s6;
        values[15] = -s7;
        values[16] = s8;
        values[17] = s9;
        values[18] = -s8;
        values[19] = -s9;
        values[20] = s10;
        values[21] = s11;
        values[22] = -s10;
        values[23] = -s11;
        values[24] = s12;
        values[25] = s13;
        values[26] = -s12;
        values[27] = -s13;
        values[28] = s14;
        values[29] = s15;
        values[30] = -s14;
        values[31] = -s15;
        values[32] = s16;
        values[33] = s17;
        values[34] = -s16;
        values[35] = -s17;
        values[36] = s18;
        values[37] = s19;
        values[38] = -s18;
        values[39] = -s19;
        values[40] = s20;
        values[41] = s21;
        values[42] = -s20;
        values[43] = -s21;
        values[44] = s22;
        values[45] = s23;
        values[46] = -s22;
        values[47] = -s23;
        values[48] = s24;
        values[49] = s25;
        values[50] = -s24;
        values[51] = -s25;
        values[52] = s26;
        values[53] = s27;
        values[54] = -s26;
        values[55] = -s27;
        values[56] = s28;
        values[57] = s29;
        values[58] = -s28;
        values[59] = -s29;
        values[60] = s30;
        values[61] = s31;
        values[62] = -s30;
        values[63] = -s31;
        values[64] = s32;
        values[65] = s33;
        values[66] = -s32;
        values[67] = -s33;
        values[68] = s34;
        values[69] = s35;
        values[70] = -s34;
        values[71] = -s35;
        values[72] = s36;
        values[73] = s37;
        values[74] = -s36;
        values[75] = -s37;
        values[76] = s38;
        values[77] = s39;
        values[78] = -s38;
        values[79] = -s39;
        values[80] = s40;
        values[81] = s41;
        values[82] = -s40;
        values[83] = -s41;
        values[84] = s42;
        values[85] = s43;
        values[86] = -s42;
        values[87] = -s43;
        values[88] = s44;
        values[89] = s45;
        values[90] = -s44;
        values[91] = -s45;
        values[92] = s46;
        values[93] = s47;
        values[94] = -s46;
        values[95] = -s47;
        values[96] = s48;
        values[97] = s49;
        values[98] = -s48;
        values[99] = -s49;
        values[100] = s50;
        values[101] = s51;
        values[102] = -s50;
        values[103] = -s51;
        values[104] = s52;
        values[105] = s53;
        values[106] = -s52;
        values[107] = -s53;
        values[108] = s54;
        values[109] = s55;
        values[110] = -s54;
        values[111] = -s55;
        values[112] = s56;
        values[113] = s57;
        values[114] = -s56;
        values[115] = -s57;
        values[116] = s58;
        values[117] = s59;
        values[118] = -s58;
        values[119] = -s59;
        values[120] = s60;
        values[121] = s61;
        values[122] = -s60;
        values[123] = -s61;
        values[124] = s62;
        values[125] = s63;
        values[126] = -s62;
        values[127] = -s63;
        values[128] = s64;
        values[129] = s65;
        values[130] = -s64;
        values[131] = -s65;
        values[132] = 1.0;
        values[133] = 1.0;
    }
    #[inline]
    fn force_jacobian_nonzeros(
        &self,
        q: &::zeitner::__private::Vector<36>,
        v: &::zeitner::__private::Vector<36>,
        t: ::zeitner::__private::Float,
        values: &mut [::zeitner::__private::Float],
    ) {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
    }
    #[inline]
    fn constraint_force_jacobian_nonzeros(
        &self,
        q: &::zeitner::__private::Vector<36>,
        v: &::zeitner::__private::Vector<36>,
        t: ::zeitner::__private::Float,
        lambda: &::zeitner::__private::Vector<35>,
        values: &mut [::zeitner::__private::Float],
    ) {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let s0 = 2.0 * lambda[0];
        let s1 = 2.0 * lambda[9];
        let s2 = 2.0 * lambda[11];
        let s3 = s0 + s1 + s2;
        let s4 = -2.0 * lambda[0];
        let s5 = -2.0 * lambda[9];
        let s6 = -2.0 * lambda[11];
        let s7 = -s0;
        let s8 = 2.0 * lambda[10];
        let s9 = s8 - s4;
        let s10 = -2.0 * lambda[10];
        let s11 = -s1;
        let s12 = 2.0 * lambda[1];
        let s13 = 2.0 * lambda[12];
        let s14 = 2.0 * lambda[14];
        let s15 = s12 - s5 + s13 + s14;
        let s16 = -2.0 * lambda[1];
        let s17 = -2.0 * lambda[12];
        let s18 = -2.0 * lambda[14];
        let s19 = -s2;
        let s20 = -s8;
        let s21 = -s12;
        let s22 = 2.0 * lambda[13];
        let s23 = -s16 - s10 - s6 + s22;
        let s24 = -2.0 * lambda[13];
        let s25 = -s13;
        let s26 = 2.0 * lambda[2];
        let s27 = 2.0 * lambda[15];
        let s28 = 2.0 * lambda[17];
        let s29 = s26 - s17 + s27 + s28;
        let s30 = -2.0 * lambda[2];
        let s31 = -2.0 * lambda[15];
        let s32 = -2.0 * lambda[17];
        let s33 = -s14;
        let s34 = -s22;
        let s35 = -s26;
        let s36 = 2.0 * lambda[16];
        let s37 = -s30 - s24 - s18 + s36;
        let s38 = -2.0 * lambda[16];
        let s39 = -s27;
        let s40 = 2.0 * lambda[3];
        let s41 = 2.0 * lambda[18];
        let s42 = 2.0 * lambda[20];
        let s43 = s40 - s31 + s41 + s42;
        let s44 = -2.0 * lambda[3];
        let s45 = -2.0 * lambda[18];
        let s46 = -2.0 * lambda[20];
        let s47 = -s28;
        let s48 = -s36;
        let s49 = -s40;
        let s50 = 2.0 * lambda[19];
        let s51 = -s44 - s38 - s32 + s50;
        let s52 = -2.0 * lambda[19];
        let s53 = -s41;
        let s54 = 2.0 * lambda[4];
        let s55 = 2.0 * lambda[21];
        let s56 = 2.0 * lambda[23];
        let s57 = s54 - s45 + s55 + s56;
        let s58 = -2.0 * lambda[4];
        let s59 = -2.0 * lambda[21];
        let s60 = -2.0 * lambda[23];
        let s61 = -s42;
        let s62 = -s50;
        let s63 = -s54;
        let s64 = 2.0 * lambda[22];
        let s65 = -s58 - s52 - s46 + s64;
        let s66 = -2.0 * lambda[22];
        let s67 = -s55;
        let s68 = 2.0 * lambda[5];
        let s69 = 2.0 * lambda[24];
        let s70 = 2.0 * lambda[26];
        let s71 = s68 - s59 + s69 + s70;
        let s72 = -2.0 * lambda[5];
        let s73 = -2.0 * lambda[24];
        let s74 = -2.0 * lambda[26];
        let s75 = -s56;
        let s76 = -s64;
        let s77 = -s68;
        let s78 = 2.0 * lambda[25];
        let s79 = -s72 - s66 - s60 + s78;
        let s80 = -2.0 * lambda[25];
        let s81 = -s69;
        let s82 = 2.0 * lambda[6];
        let s83 = 2.0 * lambda[27];
        let s84 = 2.0 * lambda[29];
        let s85 = s82 - s73 + s83 + s84;
        let s86 = -2.0 * lambda[6];
        let s87 = -2.0 * lambda[27];
        let s88 = -2.0 * lambda[29];
        let s89 = -s70;
        let s90 = -s78;
        let s91 = -s82;
        let s92 = 2.0 * lambda[28];
        let s93 = -s86 - s80 - s74 + s92;
        let s94 = -2.0 * lambda[28];
        let s95 = -s83;
        let s96 = 2.0 * lambda[7];
        let s97 = 2.0 * lambda[30];
        let s98 = 2.0 * lambda[32];
        let s99 = s96 - s87 + s97 + s98;
        let s100 = -2.0 * lambda[7];
        let s101 = -2.0 * lambda[30];
        let s102 = -2.0 * lambda[32];
        let s103 = -s84;
        let s104 = -s92;
        let s105 = -s96;
        let s106 = 2.0 * lambda[31];
        let s107 = -s100 - s94 - s88 + s106;
        let s108 = -2.0 * lambda[31];
        let s109 = -s97;
        let s110 = 2.0 * lambda[8];
        let s111 = s110 - s101;
        let s112 = -2.0 * lambda[8];
        let s113 = -s98;
        let s114 = -s106;
        let s115 = -s110;
        let s116 = -s112 - s108 - s102;
        values[0] = s3;
        values[1] = s4;
        values[2] = s5;
        values[3] = s6;
        values[4] = s3;
        values[5] = s4;
        values[6] = s5;
        values[7] = s6;
        values[8] = s7;
        values[9] = s9;
        values[10] = s10;
        values[11] = s7;
        values[12] = s9;
        values[13] = s10;
        values[14] = s11;
        values[15] = s15;
        values[16] = s16;
        values[17] = s17;
        values[18] = s18;
        values[19] = s11;
        values[20] = s15;
        values[21] = s16;
        values[22] = s17;
        values[23] = s18;
        values[24] = s19;
        values[25] = s20;
        values[26] = s21;
        values[27] = s23;
        values[28] = s24;
        values[29] = s19;
        values[30] = s20;
        values[31] = s21;
        values[32] = s23;
        values[33] = s24;
        values[34] = s25;
        values[35] = s29;
        values[36] = s30;
        values[37] = s31;
        values[38] = s32;
        values[39] = s25;
        values[40] = s29;
        values[41] = s30;
        values[42] = s31;
        values[43] = s32;
        values[44] = s33;
        values[45] = s34;
        values[46] = s35;
        values[47] = s37;
        values[48] = s38;
        values[49] = s33;
        values[50] = s34;
        values[51] = s35;
        values[52] = s37;
        values[53] = s38;
        values[54] = s39;
        values[55] = s43;
        values[56] = s44;
        values[57] = s45;
        values[58] = s46;
        values[59] = s39;
        values[60] = s43;
        values[61] = s44;
        values[62] = s45;
        values[63] = s46;
        values[64] = s47;
        values[65] = s48;
        values[66] = s49;
        values[67] = s51;
        values[68] = s52;
        values[69] = s47;
        values[70] = s48;
        values[71] = s49;
        values[72] = s51;
        values[73] = s52;
        values[74] = s53;
        values[75] = s57;
        values[76] = s58;
        values[77] = s59;
        values[78] = s60;
        values[79] = s53;
        values[80] = s57;
        values[81] = s58;
        values[82] = s59;
        values[83] = s60;
        values[84] = s61;
        values[85] = s62;
        values[86] = s63;
        values[87] = s65;
        values[88] = s66;
        values[89] = s61;
        values[90] = s62;
        values[91] = s63;
        values[92] = s65;
        values[93] = s66;
        values[94] = s67;
        values[95] = s71;
        values[96] = s72;
        values[97] = s73;
        values[98] = s74;
        values[99] = s67;
        values[100] = s71;
        values[101] = s72;
        values[102] = s73;
        values[103] = s74;
        values[104] = s75;
        values[105] = s76;
        values[106] = s77;
        values[107] = s79;
        values[108] = s80;
        values[109] = s75;
        values[110] = s76;
        values[111] = s77;
        values[112] = s79;
        values[113] = s80;
        values[114] = s81;
        values[115] = s85;
        values[116] = s86;
        values[117] = s87;
        values[118] = s88;
        values[119] = s81;
        values[120] = s85;
        values[121] = s86;
        values[122] = s87;
        values[123] = s88;
        values[124] = s89;
        values[125] = s90;
        values[126] = s91;
        values[127] = s93;
        values[128] = s94;
        values[129] = s89;
        values[130] = s90;
        values[131] = s91;
        values[132] = s93;
        values[133] = s94;
        values[134] = s95;
        values[135] = s99;
        values[136] = s100;
        values[137] = s101;
        values[138] = s102;
        values[139] = s95;
        values[140] = s99;
        values[141] = s100;
        values[142] = s101;
        values[143] = s102;
        values[144] = s103;
        values[145] = s104;
        values[146] = s105;
        values[147] = s107;
        values[148] = s108;
        values[149] = s103;
        values[150] = s104;
        values[151] = s105;
        values[152] = s107;
        values[153] = s108;
        values[154] = s109;
        values[155] = s111;
        values[156] = s112;
        values[157] = s109;
        values[158] = s111;
        values[159] = s112;
        values[160] = s113;
        values[161] = s114;
        values[162] = s115;
        values[163] = s116;
        values[164] = s113;
        values[165] = s114;
        values[166] = s115;
        values[167] = s116;
    }
}
#[allow(dead_code)]
impl PinnedLadder8 {
    const BAYS: usize = 8;
    const NODES: usize = 2 * (Self::BAYS + 1);
    const BARS: usize = (Self::BAYS + 1) + 3 * Self::BAYS;
    fn bar(&self, p: [Float; 2], r: [Float; 2], length2: Float) -> Float {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        (p[0] - r[0]).powi(2) + (p[1] - r[1]).powi(2) - length2
    }
    fn mass(&self) -> [Float; 2 * Self::NODES] {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        [self.m; 2 * Self::NODES]
    }
    fn force(&self) -> [Float; 2 * Self::NODES] {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let mut f = [0.0; 2 * Self::NODES];
        for node in 0..Self::NODES {
            f[2 * node + 1] = -self.m * self.g;
        }
        f
    }
    fn constraints(&self, q: [Float; 2 * Self::NODES]) -> [Float; Self::BARS + 4] {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let a2 = self.a * self.a;
        let mut g = [0.0; Self::BARS + 4];
        let mut row = 0;
        for k in 0..=Self::BAYS {
            let (b, t) = (4 * k, 4 * k + 2);
            g[row] = self.bar([q[b], q[b + 1]], [q[t], q[t + 1]], a2);
            row += 1;
        }
        for k in 0..Self::BAYS {
            let (b, t, nb, nt) = (4 * k, 4 * k + 2, 4 * k + 4, 4 * k + 6);
            g[row] = self.bar([q[b], q[b + 1]], [q[nb], q[nb + 1]], a2);
            g[row + 1] = self.bar([q[t], q[t + 1]], [q[nt], q[nt + 1]], a2);
            g[row + 2] = self.bar([q[b], q[b + 1]], [q[nt], q[nt + 1]], 2.0 * a2);
            row += 3;
        }
        let last = 4 * Self::BAYS;
        g[row] = q[0];
        g[row + 1] = q[1];
        g[row + 2] = q[last] - Self::BAYS as Float * self.a;
        g[row + 3] = q[last + 1];
        g
    }
}
#[allow(unused_variables, unused_mut, clippy::all)]
impl ::zeitner::__private::ConstrainedSystem<36, 37> for PinnedLadder8 {
    const POSITION_CONSTRAINTS: usize = 37;
    const MASS_IS_CONSTANT: bool = true;
    const DYNAMICS_DEPEND_ON_VELOCITY: bool = false;
    const SUMMARY: ::zeitner::__private::SceneSummary = ::zeitner::__private::SceneSummary {
        coordinates: 36,
        position_constraints: 37,
        velocity_constraints: 0,
        mass: ::zeitner::__private::MassKind::ConstantDiagonal,
        time_dependent: false,
        functions: &[
            ::zeitner::__private::FunctionSummary {
                name: "mass_matrix",
                blocks: &[
                    ::zeitner::__private::BlockSummary {
                        name: "m",
                        rows: 36,
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
                        rows: 36,
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
                    adds: 18u64,
                    muls: 18u64,
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
                        rows: 37,
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
                        ],
                    },
                ],
                ops: ::zeitner::__private::OpCounts {
                    adds: 133u64,
                    muls: 69u64,
                    divs: 0u64,
                    transcendental: 0u64,
                    opaque_calls: 0u64,
                },
                ops_unshared: ::zeitner::__private::OpCounts {
                    adds: 133u64,
                    muls: 108u64,
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
                        rows: 37,
                        cols: 36,
                        nonzeros: &[
                            (0, 0),
                            (0, 1),
                            (0, 2),
                            (0, 3),
                            (1, 4),
                            (1, 5),
                            (1, 6),
                            (1, 7),
                            (2, 8),
                            (2, 9),
                            (2, 10),
                            (2, 11),
                            (3, 12),
                            (3, 13),
                            (3, 14),
                            (3, 15),
                            (4, 16),
                            (4, 17),
                            (4, 18),
                            (4, 19),
                            (5, 20),
                            (5, 21),
                            (5, 22),
                            (5, 23),
                            (6, 24),
                            (6, 25),
                            (6, 26),
                            (6, 27),
                            (7, 28),
                            (7, 29),
                            (7, 30),
                            (7, 31),
                            (8, 32),
                            (8, 33),
                            (8, 34),
                            (8, 35),
                            (9, 0),
                            (9, 1),
                            (9, 4),
                            (9, 5),
                            (10, 2),
                            (10, 3),
                            (10, 6),
                            (10, 7),
                            (11, 0),
                            (11, 1),
                            (11, 6),
                            (11, 7),
                            (12, 4),
                            (12, 5),
                            (12, 8),
                            (12, 9),
                            (13, 6),
                            (13, 7),
                            (13, 10),
                            (13, 11),
                            (14, 4),
                            (14, 5),
                            (14, 10),
                            (14, 11),
                            (15, 8),
                            (15, 9),
                            (15, 12),
                            (15, 13),
                            (16, 10),
                            (16, 11),
                            (16, 14),
                            (16, 15),
                            (17, 8),
                            (17, 9),
                            (17, 14),
                            (17, 15),
                            (18, 12),
                            (18, 13),
                            (18, 16),
                            (18, 17),
                            (19, 14),
                            (19, 15),
                            (19, 18),
                            (19, 19),
                            (20, 12),
                            (20, 13),
                            (20, 18),
                            (20, 19),
                            (21, 16),
                            (21, 17),
                            (21, 20),
                            (21, 21),
                            (22, 18),
                            (22, 19),
                            (22, 22),
                            (22, 23),
                            (23, 16),
                            (23, 17),
                            (23, 22),
                            (23, 23),
                            (24, 20),
                            (24, 21),
                            (24, 24),
                            (24, 25),
                            (25, 22),
                            (25, 23),
                            (25, 26),
                            (25, 27),
                            (26, 20),
                            (26, 21),
                            (26, 26),
                            (26, 27),
                            (27, 24),
                            (27, 25),
                            (27, 28),
                            (27, 29),
                            (28, 26),
                            (28, 27),
                            (28, 30),
                            (28, 31),
                            (29, 24),
                            (29, 25),
                            (29, 30),
                            (29, 31),
                            (30, 28),
                            (30, 29),
                            (30, 32),
                            (30, 33),
                            (31, 30),
                            (31, 31),
                            (31, 34),
                            (31, 35),
                            (32, 28),
                            (32, 29),
                            (32, 34),
                            (32, 35),
                            (33, 0),
                            (34, 1),
                            (35, 32),
                            (36, 33),
                        ],
                    },
                ],
                ops: ::zeitner::__private::OpCounts {
                    adds: 132u64,
                    muls: 66u64,
                    divs: 0u64,
                    transcendental: 0u64,
                    opaque_calls: 0u64,
                },
                ops_unshared: ::zeitner::__private::OpCounts {
                    adds: 198u64,
                    muls: 132u64,
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
                        rows: 37,
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
                        ],
                    },
                ],
                ops: ::zeitner::__private::OpCounts {
                    adds: 165u64,
                    muls: 198u64,
                    divs: 0u64,
                    transcendental: 0u64,
                    opaque_calls: 0u64,
                },
                ops_unshared: ::zeitner::__private::OpCounts {
                    adds: 231u64,
                    muls: 264u64,
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
                        rows: 37,
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
                        ],
                    },
                ],
                ops: ::zeitner::__private::OpCounts {
                    adds: 231u64,
                    muls: 204u64,
                    divs: 0u64,
                    transcendental: 0u64,
                    opaque_calls: 0u64,
                },
                ops_unshared: ::zeitner::__private::OpCounts {
                    adds: 231u64,
                    muls: 396u64,
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
                        rows: 36,
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
                        ],
                    },
                    ::zeitner::__private::BlockSummary {
                        name: "f",
                        rows: 36,
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
                        ],
                    },
                    ::zeitner::__private::BlockSummary {
                        name: "g",
                        rows: 37,
                        cols: 36,
                        nonzeros: &[
                            (0, 0),
                            (0, 1),
                            (0, 2),
                            (0, 3),
                            (1, 4),
                            (1, 5),
                            (1, 6),
                            (1, 7),
                            (2, 8),
                            (2, 9),
                            (2, 10),
                            (2, 11),
                            (3, 12),
                            (3, 13),
                            (3, 14),
                            (3, 15),
                            (4, 16),
                            (4, 17),
                            (4, 18),
                            (4, 19),
                            (5, 20),
                            (5, 21),
                            (5, 22),
                            (5, 23),
                            (6, 24),
                            (6, 25),
                            (6, 26),
                            (6, 27),
                            (7, 28),
                            (7, 29),
                            (7, 30),
                            (7, 31),
                            (8, 32),
                            (8, 33),
                            (8, 34),
                            (8, 35),
                            (9, 0),
                            (9, 1),
                            (9, 4),
                            (9, 5),
                            (10, 2),
                            (10, 3),
                            (10, 6),
                            (10, 7),
                            (11, 0),
                            (11, 1),
                            (11, 6),
                            (11, 7),
                            (12, 4),
                            (12, 5),
                            (12, 8),
                            (12, 9),
                            (13, 6),
                            (13, 7),
                            (13, 10),
                            (13, 11),
                            (14, 4),
                            (14, 5),
                            (14, 10),
                            (14, 11),
                            (15, 8),
                            (15, 9),
                            (15, 12),
                            (15, 13),
                            (16, 10),
                            (16, 11),
                            (16, 14),
                            (16, 15),
                            (17, 8),
                            (17, 9),
                            (17, 14),
                            (17, 15),
                            (18, 12),
                            (18, 13),
                            (18, 16),
                            (18, 17),
                            (19, 14),
                            (19, 15),
                            (19, 18),
                            (19, 19),
                            (20, 12),
                            (20, 13),
                            (20, 18),
                            (20, 19),
                            (21, 16),
                            (21, 17),
                            (21, 20),
                            (21, 21),
                            (22, 18),
                            (22, 19),
                            (22, 22),
                            (22, 23),
                            (23, 16),
                            (23, 17),
                            (23, 22),
                            (23, 23),
                            (24, 20),
                            (24, 21),
                            (24, 24),
                            (24, 25),
                            (25, 22),
                            (25, 23),
                            (25, 26),
                            (25, 27),
                            (26, 20),
                            (26, 21),
                            (26, 26),
                            (26, 27),
                            (27, 24),
                            (27, 25),
                            (27, 28),
                            (27, 29),
                            (28, 26),
                            (28, 27),
                            (28, 30),
                            (28, 31),
                            (29, 24),
                            (29, 25),
                            (29, 30),
                            (29, 31),
                            (30, 28),
                            (30, 29),
                            (30, 32),
                            (30, 33),
                            (31, 30),
                            (31, 31),
                            (31, 34),
                            (31, 35),
                            (32, 28),
                            (32, 29),
                            (32, 34),
                            (32, 35),
                            (33, 0),
                            (34, 1),
                            (35, 32),
                            (36, 33),
                        ],
                    },
                    ::zeitner::__private::BlockSummary {
                        name: "b",
                        rows: 37,
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
                        ],
                    },
                ],
                ops: ::zeitner::__private::OpCounts {
                    adds: 364u64,
                    muls: 271u64,
                    divs: 0u64,
                    transcendental: 0u64,
                    opaque_calls: 0u64,
                },
                ops_unshared: ::zeitner::__private::OpCounts {
                    adds: 447u64,
                    muls: 546u64,
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
                        rows: 36,
                        cols: 36,
                        nonzeros: &[],
                    },
                    ::zeitner::__private::BlockSummary {
                        name: "dv",
                        rows: 36,
                        cols: 36,
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
                        rows: 36,
                        cols: 36,
                        nonzeros: &[
                            (0, 0),
                            (0, 2),
                            (0, 4),
                            (0, 6),
                            (1, 1),
                            (1, 3),
                            (1, 5),
                            (1, 7),
                            (2, 0),
                            (2, 2),
                            (2, 6),
                            (3, 1),
                            (3, 3),
                            (3, 7),
                            (4, 0),
                            (4, 4),
                            (4, 6),
                            (4, 8),
                            (4, 10),
                            (5, 1),
                            (5, 5),
                            (5, 7),
                            (5, 9),
                            (5, 11),
                            (6, 0),
                            (6, 2),
                            (6, 4),
                            (6, 6),
                            (6, 10),
                            (7, 1),
                            (7, 3),
                            (7, 5),
                            (7, 7),
                            (7, 11),
                            (8, 4),
                            (8, 8),
                            (8, 10),
                            (8, 12),
                            (8, 14),
                            (9, 5),
                            (9, 9),
                            (9, 11),
                            (9, 13),
                            (9, 15),
                            (10, 4),
                            (10, 6),
                            (10, 8),
                            (10, 10),
                            (10, 14),
                            (11, 5),
                            (11, 7),
                            (11, 9),
                            (11, 11),
                            (11, 15),
                            (12, 8),
                            (12, 12),
                            (12, 14),
                            (12, 16),
                            (12, 18),
                            (13, 9),
                            (13, 13),
                            (13, 15),
                            (13, 17),
                            (13, 19),
                            (14, 8),
                            (14, 10),
                            (14, 12),
                            (14, 14),
                            (14, 18),
                            (15, 9),
                            (15, 11),
                            (15, 13),
                            (15, 15),
                            (15, 19),
                            (16, 12),
                            (16, 16),
                            (16, 18),
                            (16, 20),
                            (16, 22),
                            (17, 13),
                            (17, 17),
                            (17, 19),
                            (17, 21),
                            (17, 23),
                            (18, 12),
                            (18, 14),
                            (18, 16),
                            (18, 18),
                            (18, 22),
                            (19, 13),
                            (19, 15),
                            (19, 17),
                            (19, 19),
                            (19, 23),
                            (20, 16),
                            (20, 20),
                            (20, 22),
                            (20, 24),
                            (20, 26),
                            (21, 17),
                            (21, 21),
                            (21, 23),
                            (21, 25),
                            (21, 27),
                            (22, 16),
                            (22, 18),
                            (22, 20),
                            (22, 22),
                            (22, 26),
                            (23, 17),
                            (23, 19),
                            (23, 21),
                            (23, 23),
                            (23, 27),
                            (24, 20),
                            (24, 24),
                            (24, 26),
                            (24, 28),
                            (24, 30),
                            (25, 21),
                            (25, 25),
                            (25, 27),
                            (25, 29),
                            (25, 31),
                            (26, 20),
                            (26, 22),
                            (26, 24),
                            (26, 26),
                            (26, 30),
                            (27, 21),
                            (27, 23),
                            (27, 25),
                            (27, 27),
                            (27, 31),
                            (28, 24),
                            (28, 28),
                            (28, 30),
                            (28, 32),
                            (28, 34),
                            (29, 25),
                            (29, 29),
                            (29, 31),
                            (29, 33),
                            (29, 35),
                            (30, 24),
                            (30, 26),
                            (30, 28),
                            (30, 30),
                            (30, 34),
                            (31, 25),
                            (31, 27),
                            (31, 29),
                            (31, 31),
                            (31, 35),
                            (32, 28),
                            (32, 32),
                            (32, 34),
                            (33, 29),
                            (33, 33),
                            (33, 35),
                            (34, 28),
                            (34, 30),
                            (34, 32),
                            (34, 34),
                            (35, 29),
                            (35, 31),
                            (35, 33),
                            (35, 35),
                        ],
                    },
                    ::zeitner::__private::BlockSummary {
                        name: "dv",
                        rows: 36,
                        cols: 36,
                        nonzeros: &[],
                    },
                ],
                ops: ::zeitner::__private::OpCounts {
                    adds: 89u64,
                    muls: 66u64,
                    divs: 0u64,
                    transcendental: 0u64,
                    opaque_calls: 0u64,
                },
                ops_unshared: ::zeitner::__private::OpCounts {
                    adds: 178u64,
                    muls: 264u64,
                    divs: 0u64,
                    transcendental: 0u64,
                    opaque_calls: 0u64,
                },
            },
        ],
    };
    type Mass = ::zeitner::__private::DiagonalMass<36>;
    type Storage = ::zeitner::__private::Dense;
    const SPARSITY: ::core::option::Option<::zeitner::__private::Sparsity> = ::core::option::Option::Some(::zeitner::__private::Sparsity {
        constraint_jacobian: &[
            (0, 0),
            (0, 1),
            (0, 2),
            (0, 3),
            (1, 4),
            (1, 5),
            (1, 6),
            (1, 7),
            (2, 8),
            (2, 9),
            (2, 10),
            (2, 11),
            (3, 12),
            (3, 13),
            (3, 14),
            (3, 15),
            (4, 16),
            (4, 17),
            (4, 18),
            (4, 19),
            (5, 20),
            (5, 21),
            (5, 22),
            (5, 23),
            (6, 24),
            (6, 25),
            (6, 26),
            (6, 27),
            (7, 28),
            (7, 29),
            (7, 30),
            (7, 31),
            (8, 32),
            (8, 33),
            (8, 34),
            (8, 35),
            (9, 0),
            (9, 1),
            (9, 4),
            (9, 5),
            (10, 2),
            (10, 3),
            (10, 6),
            (10, 7),
            (11, 0),
            (11, 1),
            (11, 6),
            (11, 7),
            (12, 4),
            (12, 5),
            (12, 8),
            (12, 9),
            (13, 6),
            (13, 7),
            (13, 10),
            (13, 11),
            (14, 4),
            (14, 5),
            (14, 10),
            (14, 11),
            (15, 8),
            (15, 9),
            (15, 12),
            (15, 13),
            (16, 10),
            (16, 11),
            (16, 14),
            (16, 15),
            (17, 8),
            (17, 9),
            (17, 14),
            (17, 15),
            (18, 12),
            (18, 13),
            (18, 16),
            (18, 17),
            (19, 14),
            (19, 15),
            (19, 18),
            (19, 19),
            (20, 12),
            (20, 13),
            (20, 18),
            (20, 19),
            (21, 16),
            (21, 17),
            (21, 20),
            (21, 21),
            (22, 18),
            (22, 19),
            (22, 22),
            (22, 23),
            (23, 16),
            (23, 17),
            (23, 22),
            (23, 23),
            (24, 20),
            (24, 21),
            (24, 24),
            (24, 25),
            (25, 22),
            (25, 23),
            (25, 26),
            (25, 27),
            (26, 20),
            (26, 21),
            (26, 26),
            (26, 27),
            (27, 24),
            (27, 25),
            (27, 28),
            (27, 29),
            (28, 26),
            (28, 27),
            (28, 30),
            (28, 31),
            (29, 24),
            (29, 25),
            (29, 30),
            (29, 31),
            (30, 28),
            (30, 29),
            (30, 32),
            (30, 33),
            (31, 30),
            (31, 31),
            (31, 34),
            (31, 35),
            (32, 28),
            (32, 29),
            (32, 34),
            (32, 35),
            (33, 0),
            (34, 1),
            (35, 32),
            (36, 33),
        ],
        force_jacobians: [&[], &[]],
        constraint_force_jacobians: [
            &[
                (0, 0),
                (0, 2),
                (0, 4),
                (0, 6),
                (1, 1),
                (1, 3),
                (1, 5),
                (1, 7),
                (2, 0),
                (2, 2),
                (2, 6),
                (3, 1),
                (3, 3),
                (3, 7),
                (4, 0),
                (4, 4),
                (4, 6),
                (4, 8),
                (4, 10),
                (5, 1),
                (5, 5),
                (5, 7),
                (5, 9),
                (5, 11),
                (6, 0),
                (6, 2),
                (6, 4),
                (6, 6),
                (6, 10),
                (7, 1),
                (7, 3),
                (7, 5),
                (7, 7),
                (7, 11),
                (8, 4),
                (8, 8),
                (8, 10),
                (8, 12),
                (8, 14),
                (9, 5),
                (9, 9),
                (9, 11),
                (9, 13),
                (9, 15),
                (10, 4),
                (10, 6),
                (10, 8),
                (10, 10),
                (10, 14),
                (11, 5),
                (11, 7),
                (11, 9),
                (11, 11),
                (11, 15),
                (12, 8),
                (12, 12),
                (12, 14),
                (12, 16),
                (12, 18),
                (13, 9),
                (13, 13),
                (13, 15),
                (13, 17),
                (13, 19),
                (14, 8),
                (14, 10),
                (14, 12),
                (14, 14),
                (14, 18),
                (15, 9),
                (15, 11),
                (15, 13),
                (15, 15),
                (15, 19),
                (16, 12),
                (16, 16),
                (16, 18),
                (16, 20),
                (16, 22),
                (17, 13),
                (17, 17),
                (17, 19),
                (17, 21),
                (17, 23),
                (18, 12),
                (18, 14),
                (18, 16),
                (18, 18),
                (18, 22),
                (19, 13),
                (19, 15),
                (19, 17),
                (19, 19),
                (19, 23),
                (20, 16),
                (20, 20),
                (20, 22),
                (20, 24),
                (20, 26),
                (21, 17),
                (21, 21),
                (21, 23),
                (21, 25),
                (21, 27),
                (22, 16),
                (22, 18),
                (22, 20),
                (22, 22),
                (22, 26),
                (23, 17),
                (23, 19),
                (23, 21),
                (23, 23),
                (23, 27),
                (24, 20),
                (24, 24),
                (24, 26),
                (24, 28),
                (24, 30),
                (25, 21),
                (25, 25),
                (25, 27),
                (25, 29),
                (25, 31),
                (26, 20),
                (26, 22),
                (26, 24),
                (26, 26),
                (26, 30),
                (27, 21),
                (27, 23),
                (27, 25),
                (27, 27),
                (27, 31),
                (28, 24),
                (28, 28),
                (28, 30),
                (28, 32),
                (28, 34),
                (29, 25),
                (29, 29),
                (29, 31),
                (29, 33),
                (29, 35),
                (30, 24),
                (30, 26),
                (30, 28),
                (30, 30),
                (30, 34),
                (31, 25),
                (31, 27),
                (31, 29),
                (31, 31),
                (31, 35),
                (32, 28),
                (32, 32),
                (32, 34),
                (33, 29),
                (33, 33),
                (33, 35),
                (34, 28),
                (34, 30),
                (34, 32),
                (34, 34),
                (35, 29),
                (35, 31),
                (35, 33),
                (35, 35),
            ],
            &[],
        ],
    });
    #[inline]
    fn mass_matrix(
        &self,
        q: &::zeitner::__private::Vector<36>,
        t: ::zeitner::__private::Float,
    ) -> Self::Mass {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let mut m = ::zeitner::__private::Vector::<36>::zeros();
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
        ::zeitner::__private::DiagonalMass(m)
    }
    #[inline]
    fn applied_force(
        &self,
        q: &::zeitner::__private::Vector<36>,
        v: &::zeitner::__private::Vector<36>,
        t: ::zeitner::__private::Float,
    ) -> ::zeitner::__private::Vector<36> {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let s0 = -(self.m * self.g);
        let mut f = ::zeitner::__private::Vector::<36>::zeros();
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
        f
    }
    #[inline]
    fn constraint_residual(
        &self,
        q: &::zeitner::__private::Vector<36>,
        v: &::zeitner::__private::Vector<36>,
        t: ::zeitner::__private::Float,
    ) -> ::zeitner::__private::Vector<37> {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let s0 = self.a.powi(2);
        let s1 = 2.0 * s0;
        let mut g = ::zeitner::__private::Vector::<37>::zeros();
        g[0] = (q[0] - q[2]).powi(2) + (q[1] - q[3]).powi(2) - s0;
        g[1] = (q[4] - q[6]).powi(2) + (q[5] - q[7]).powi(2) - s0;
        g[2] = (q[8] - q[10]).powi(2) + (q[9] - q[11]).powi(2) - s0;
        g[3] = (q[12] - q[14]).powi(2) + (q[13] - q[15]).powi(2) - s0;
        g[4] = (q[16] - q[18]).powi(2) + (q[17] - q[19]).powi(2) - s0;
        g[5] = (q[20] - q[22]).powi(2) + (q[21] - q[23]).powi(2) - s0;
        g[6] = (q[24] - q[26]).powi(2) + (q[25] - q[27]).powi(2) - s0;
        g[7] = (q[28] - q[30]).powi(2) + (q[29] - q[31]).powi(2) - s0;
        g[8] = (q[32] - q[34]).powi(2) + (q[33] - q[35]).powi(2) - s0;
        g[9] = (q[0] - q[4]).powi(2) + (q[1] - q[5]).powi(2) - s0;
        g[10] = (q[2] - q[6]).powi(2) + (q[3] - q[7]).powi(2) - s0;
        g[11] = (q[0] - q[6]).powi(2) + (q[1] - q[7]).powi(2) - s1;
        g[12] = (q[4] - q[8]).powi(2) + (q[5] - q[9]).powi(2) - s0;
        g[13] = (q[6] - q[10]).powi(2) + (q[7] - q[11]).powi(2) - s0;
        g[14] = (q[4] - q[10]).powi(2) + (q[5] - q[11]).powi(2) - s1;
        g[15] = (q[8] - q[12]).powi(2) + (q[9] - q[13]).powi(2) - s0;
        g[16] = (q[10] - q[14]).powi(2) + (q[11] - q[15]).powi(2) - s0;
        g[17] = (q[8] - q[14]).powi(2) + (q[9] - q[15]).powi(2) - s1;
        g[18] = (q[12] - q[16]).powi(2) + (q[13] - q[17]).powi(2) - s0;
        g[19] = (q[14] - q[18]).powi(2) + (q[15] - q[19]).powi(2) - s0;
        g[20] = (q[12] - q[18]).powi(2) + (q[13] - q[19]).powi(2) - s1;
        g[21] = (q[16] - q[20]).powi(2) + (q[17] - q[21]).powi(2) - s0;
        g[22] = (q[18] - q[22]).powi(2) + (q[19] - q[23]).powi(2) - s0;
        g[23] = (q[16] - q[22]).powi(2) + (q[17] - q[23]).powi(2) - s1;
        g[24] = (q[20] - q[24]).powi(2) + (q[21] - q[25]).powi(2) - s0;
        g[25] = (q[22] - q[26]).powi(2) + (q[23] - q[27]).powi(2) - s0;
        g[26] = (q[20] - q[26]).powi(2) + (q[21] - q[27]).powi(2) - s1;
        g[27] = (q[24] - q[28]).powi(2) + (q[25] - q[29]).powi(2) - s0;
        g[28] = (q[26] - q[30]).powi(2) + (q[27] - q[31]).powi(2) - s0;
        g[29] = (q[24] - q[30]).powi(2) + (q[25] - q[31]).powi(2) - s1;
        g[30] = (q[28] - q[32]).powi(2) + (q[29] - q[33]).powi(2) - s0;
        g[31] = (q[30] - q[34]).powi(2) + (q[31] - q[35]).powi(2) - s0;
        g[32] = (q[28] - q[34]).powi(2) + (q[29] - q[35]).powi(2) - s1;
        g[33] = q[0];
        g[34] = q[1];
        g[35] = q[32] - 8.0 * self.a;
        g[36] = q[33];
        g
    }
    #[inline]
    fn constraint_jacobian(
        &self,
        q: &::zeitner::__private::Vector<36>,
        v: &::zeitner::__private::Vector<36>,
        t: ::zeitner::__private::Float,
    ) -> ::zeitner::__private::Matrix<37, 36> {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let s0 = 2.0 * (q[0] - q[2]);
        let s1 = 2.0 * (q[1] - q[3]);
        let s2 = 2.0 * (q[4] - q[6]);
        let s3 = 2.0 * (q[5] - q[7]);
        let s4 = 2.0 * (q[8] - q[10]);
        let s5 = 2.0 * (q[9] - q[11]);
        let s6 = 2.0 * (q[12] - q[14]);
        let s7 = 2.0 * (q[13] - q[15]);
        let s8 = 2.0 * (q[16] - q[18]);
        let s9 = 2.0 * (q[17] - q[19]);
        let s10 = 2.0 * (q[20] - q[22]);
        let s11 = 2.0 * (q[21] - q[23]);
        let s12 = 2.0 * (q[24] - q[26]);
        let s13 = 2.0 * (q[25] - q[27]);
        let s14 = 2.0 * (q[28] - q[30]);
        let s15 = 2.0 * (q[29] - q[31]);
        let s16 = 2.0 * (q[32] - q[34]);
        let s17 = 2.0 * (q[33] - q[35]);
        let s18 = 2.0 * (q[0] - q[4]);
        let s19 = 2.0 * (q[1] - q[5]);
        let s20 = 2.0 * (q[2] - q[6]);
        let s21 = 2.0 * (q[3] - q[7]);
        let s22 = 2.0 * (q[0] - q[6]);
        let s23 = 2.0 * (q[1] - q[7]);
        let s24 = 2.0 * (q[4] - q[8]);
        let s25 = 2.0 * (q[5] - q[9]);
        let s26 = 2.0 * (q[6] - q[10]);
        let s27 = 2.0 * (q[7] - q[11]);
        let s28 = 2.0 * (q[4] - q[10]);
        let s29 = 2.0 * (q[5] - q[11]);
        let s30 = 2.0 * (q[8] - q[12]);
        let s31 = 2.0 * (q[9] - q[13]);
        let s32 = 2.0 * (q[10] - q[14]);
        let s33 = 2.0 * (q[11] - q[15]);
        let s34 = 2.0 * (q[8] - q[14]);
        let s35 = 2.0 * (q[9] - q[15]);
        let s36 = 2.0 * (q[12] - q[16]);
        let s37 = 2.0 * (q[13] - q[17]);
        let s38 = 2.0 * (q[14] - q[18]);
        let s39 = 2.0 * (q[15] - q[19]);
        let s40 = 2.0 * (q[12] - q[18]);
        let s41 = 2.0 * (q[13] - q[19]);
        let s42 = 2.0 * (q[16] - q[20]);
        let s43 = 2.0 * (q[17] - q[21]);
        let s44 = 2.0 * (q[18] - q[22]);
        let s45 = 2.0 * (q[19] - q[23]);
        let s46 = 2.0 * (q[16] - q[22]);
        let s47 = 2.0 * (q[17] - q[23]);
        let s48 = 2.0 * (q[20] - q[24]);
        let s49 = 2.0 * (q[21] - q[25]);
        let s50 = 2.0 * (q[22] - q[26]);
        let s51 = 2.0 * (q[23] - q[27]);
        let s52 = 2.0 * (q[20] - q[26]);
        let s53 = 2.0 * (q[21] - q[27]);
        let s54 = 2.0 * (q[24] - q[28]);
        let s55 = 2.0 * (q[25] - q[29]);
        let s56 = 2.0 * (q[26] - q[30]);
        let s57 = 2.0 * (q[27] - q[31]);
        let s58 = 2.0 * (q[24] - q[30]);
        let s59 = 2.0 * (q[25] - q[31]);
        let s60 = 2.0 * (q[28] - q[32]);
        let s61 = 2.0 * (q[29] - q[33]);
        let s62 = 2.0 * (q[30] - q[34]);
        let s63 = 2.0 * (q[31] - q[35]);
        let s64 = 2.0 * (q[28] - q[34]);
        let s65 = 2.0 * (q[29] - q[35]);
        let mut g = ::zeitner::__private::Matrix::<37, 36>::zeros();
        g[(0, 0)] = s0;
        g[(0, 1)] = s1;
        g[(0, 2)] = -s0;
        g[(0, 3)] = -s1;
        g[(1, 4)] = s2;
        g[(1, 5)] = s3;
        g[(1, 6)] = -s2;
        g[(1, 7)] = -s3;
        g[(2, 8)] = s4;
        g[(2, 9)] = s5;
        g[(2, 10)] = -s4;
        g[(2, 11)] = -s5;
        g[(3, 12)] = s6;
        g[(3, 13)] = s7;
        g[(3, 14)] = -s6;
        g[(3, 15)] = -s7;
        g[(4, 16)] = s8;
        g[(4, 17)] = s9;
        g[(4, 18)] = -s8;
        g[(4, 19)] = -s9;
        g[(5, 20)] = s10;
        g[(5, 21)] = s11;
        g[(5, 22)] = -s10;
        g[(5, 23)] = -s11;
        g[(6, 24)] = s12;
        g[(6, 25)] = s13;
        g[(6, 26)] = -s12;
        g[(6, 27)] = -s13;
        g[(7, 28)] = s14;
        g[(7, 29)] = s15;
        g[(7, 30)] = -s14;
        g[(7, 31)] = -s15;
        g[(8, 32)] = s16;
        g[(8, 33)] = s17;
        g[(8, 34)] = -s16;
        g[(8, 35)] = -s17;
        g[(9, 0)] = s18;
        g[(9, 1)] = s19;
        g[(9, 4)] = -s18;
        g[(9, 5)] = -s19;
        g[(10, 2)] = s20;
        g[(10, 3)] = s21;
        g[(10, 6)] = -s20;
        g[(10, 7)] = -s21;
        g[(11, 0)] = s22;
        g[(11, 1)] = s23;
        g[(11, 6)] = -s22;
        g[(11, 7)] = -s23;
        g[(12, 4)] = s24;
        g[(12, 5)] = s25;
        g[(12, 8)] = -s24;
        g[(12, 9)] = -s25;
        g[(13, 6)] = s26;
        g[(13, 7)] = s27;
        g[(13, 10)] = -s26;
        g[(13, 11)] = -s27;
        g[(14, 4)] = s28;
        g[(14, 5)] = s29;
        g[(14, 10)] = -s28;
        g[(14, 11)] = -s29;
        g[(15, 8)] = s30;
        g[(15, 9)] = s31;
        g[(15, 12)] = -s30;
        g[(15, 13)] = -s31;
        g[(16, 10)] = s32;
        g[(16, 11)] = s33;
        g[(16, 14)] = -s32;
        g[(16, 15)] = -s33;
        g[(17, 8)] = s34;
        g[(17, 9)] = s35;
        g[(17, 14)] = -s34;
        g[(17, 15)] = -s35;
        g[(18, 12)] = s36;
        g[(18, 13)] = s37;
        g[(18, 16)] = -s36;
        g[(18, 17)] = -s37;
        g[(19, 14)] = s38;
        g[(19, 15)] = s39;
        g[(19, 18)] = -s38;
        g[(19, 19)] = -s39;
        g[(20, 12)] = s40;
        g[(20, 13)] = s41;
        g[(20, 18)] = -s40;
        g[(20, 19)] = -s41;
        g[(21, 16)] = s42;
        g[(21, 17)] = s43;
        g[(21, 20)] = -s42;
        g[(21, 21)] = -s43;
        g[(22, 18)] = s44;
        g[(22, 19)] = s45;
        g[(22, 22)] = -s44;
        g[(22, 23)] = -s45;
        g[(23, 16)] = s46;
        g[(23, 17)] = s47;
        g[(23, 22)] = -s46;
        g[(23, 23)] = -s47;
        g[(24, 20)] = s48;
        g[(24, 21)] = s49;
        g[(24, 24)] = -s48;
        g[(24, 25)] = -s49;
        g[(25, 22)] = s50;
        g[(25, 23)] = s51;
        g[(25, 26)] = -s50;
        g[(25, 27)] = -s51;
        g[(26, 20)] = s52;
        g[(26, 21)] = s53;
        g[(26, 26)] = -s52;
        g[(26, 27)] = -s53;
        g[(27, 24)] = s54;
        g[(27, 25)] = s55;
        g[(27, 28)] = -s54;
        g[(27, 29)] = -s55;
        g[(28, 26)] = s56;
        g[(28, 27)] = s57;
        g[(28, 30)] = -s56;
        g[(28, 31)] = -s57;
        g[(29, 24)] = s58;
        g[(29, 25)] = s59;
        g[(29, 30)] = -s58;
        g[(29, 31)] = -s59;
        g[(30, 28)] = s60;
        g[(30, 29)] = s61;
        g[(30, 32)] = -s60;
        g[(30, 33)] = -s61;
        g[(31, 30)] = s62;
        g[(31, 31)] = s63;
        g[(31, 34)] = -s62;
        g[(31, 35)] = -s63;
        g[(32, 28)] = s64;
        g[(32, 29)] = s65;
        g[(32, 34)] = -s64;
        g[(32, 35)] = -s65;
        g[(33, 0)] = 1.0;
        g[(34, 1)] = 1.0;
        g[(35, 32)] = 1.0;
        g[(36, 33)] = 1.0;
        g
    }
    #[inline]
    fn constraint_rate(
        &self,
        q: &::zeitner::__private::Vector<36>,
        v: &::zeitner::__private::Vector<36>,
        t: ::zeitner::__private::Float,
    ) -> ::zeitner::__private::Vector<37> {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let s0 = 2.0 * (q[0] - q[2]);
        let s1 = 2.0 * (q[1] - q[3]);
        let s2 = 2.0 * (q[4] - q[6]);
        let s3 = 2.0 * (q[5] - q[7]);
        let s4 = 2.0 * (q[8] - q[10]);
        let s5 = 2.0 * (q[9] - q[11]);
        let s6 = 2.0 * (q[12] - q[14]);
        let s7 = 2.0 * (q[13] - q[15]);
        let s8 = 2.0 * (q[16] - q[18]);
        let s9 = 2.0 * (q[17] - q[19]);
        let s10 = 2.0 * (q[20] - q[22]);
        let s11 = 2.0 * (q[21] - q[23]);
        let s12 = 2.0 * (q[24] - q[26]);
        let s13 = 2.0 * (q[25] - q[27]);
        let s14 = 2.0 * (q[28] - q[30]);
        let s15 = 2.0 * (q[29] - q[31]);
        let s16 = 2.0 * (q[32] - q[34]);
        let s17 = 2.0 * (q[33] - q[35]);
        let s18 = 2.0 * (q[0] - q[4]);
        let s19 = 2.0 * (q[1] - q[5]);
        let s20 = 2.0 * (q[2] - q[6]);
        let s21 = 2.0 * (q[3] - q[7]);
        let s22 = 2.0 * (q[0] - q[6]);
        let s23 = 2.0 * (q[1] - q[7]);
        let s24 = 2.0 * (q[4] - q[8]);
        let s25 = 2.0 * (q[5] - q[9]);
        let s26 = 2.0 * (q[6] - q[10]);
        let s27 = 2.0 * (q[7] - q[11]);
        let s28 = 2.0 * (q[4] - q[10]);
        let s29 = 2.0 * (q[5] - q[11]);
        let s30 = 2.0 * (q[8] - q[12]);
        let s31 = 2.0 * (q[9] - q[13]);
        let s32 = 2.0 * (q[10] - q[14]);
        let s33 = 2.0 * (q[11] - q[15]);
        let s34 = 2.0 * (q[8] - q[14]);
        let s35 = 2.0 * (q[9] - q[15]);
        let s36 = 2.0 * (q[12] - q[16]);
        let s37 = 2.0 * (q[13] - q[17]);
        let s38 = 2.0 * (q[14] - q[18]);
        let s39 = 2.0 * (q[15] - q[19]);
        let s40 = 2.0 * (q[12] - q[18]);
        let s41 = 2.0 * (q[13] - q[19]);
        let s42 = 2.0 * (q[16] - q[20]);
        let s43 = 2.0 * (q[17] - q[21]);
        let s44 = 2.0 * (q[18] - q[22]);
        let s45 = 2.0 * (q[19] - q[23]);
        let s46 = 2.0 * (q[16] - q[22]);
        let s47 = 2.0 * (q[17] - q[23]);
        let s48 = 2.0 * (q[20] - q[24]);
        let s49 = 2.0 * (q[21] - q[25]);
        let s50 = 2.0 * (q[22] - q[26]);
        let s51 = 2.0 * (q[23] - q[27]);
        let s52 = 2.0 * (q[20] - q[26]);
        let s53 = 2.0 * (q[21] - q[27]);
        let s54 = 2.0 * (q[24] - q[28]);
        let s55 = 2.0 * (q[25] - q[29]);
        let s56 = 2.0 * (q[26] - q[30]);
        let s57 = 2.0 * (q[27] - q[31]);
        let s58 = 2.0 * (q[24] - q[30]);
        let s59 = 2.0 * (q[25] - q[31]);
        let s60 = 2.0 * (q[28] - q[32]);
        let s61 = 2.0 * (q[29] - q[33]);
        let s62 = 2.0 * (q[30] - q[34]);
        let s63 = 2.0 * (q[31] - q[35]);
        let s64 = 2.0 * (q[28] - q[34]);
        let s65 = 2.0 * (q[29] - q[35]);
        let mut w = ::zeitner::__private::Vector::<37>::zeros();
        w[0] = s0 * v[0] + s1 * v[1] - s0 * v[2] - s1 * v[3];
        w[1] = s2 * v[4] + s3 * v[5] - s2 * v[6] - s3 * v[7];
        w[2] = s4 * v[8] + s5 * v[9] - s4 * v[10] - s5 * v[11];
        w[3] = s6 * v[12] + s7 * v[13] - s6 * v[14] - s7 * v[15];
        w[4] = s8 * v[16] + s9 * v[17] - s8 * v[18] - s9 * v[19];
        w[5] = s10 * v[20] + s11 * v[21] - s10 * v[22] - s11 * v[23];
        w[6] = s12 * v[24] + s13 * v[25] - s12 * v[26] - s13 * v[27];
        w[7] = s14 * v[28] + s15 * v[29] - s14 * v[30] - s15 * v[31];
        w[8] = s16 * v[32] + s17 * v[33] - s16 * v[34] - s17 * v[35];
        w[9] = s18 * v[0] + s19 * v[1] - s18 * v[4] - s19 * v[5];
        w[10] = s20 * v[2] + s21 * v[3] - s20 * v[6] - s21 * v[7];
        w[11] = s22 * v[0] + s23 * v[1] - s22 * v[6] - s23 * v[7];
        w[12] = s24 * v[4] + s25 * v[5] - s24 * v[8] - s25 * v[9];
        w[13] = s26 * v[6] + s27 * v[7] - s26 * v[10] - s27 * v[11];
        w[14] = s28 * v[4] + s29 * v[5] - s28 * v[10] - s29 * v[11];
        w[15] = s30 * v[8] + s31 * v[9] - s30 * v[12] - s31 * v[13];
        w[16] = s32 * v[10] + s33 * v[11] - s32 * v[14] - s33 * v[15];
        w[17] = s34 * v[8] + s35 * v[9] - s34 * v[14] - s35 * v[15];
        w[18] = s36 * v[12] + s37 * v[13] - s36 * v[16] - s37 * v[17];
        w[19] = s38 * v[14] + s39 * v[15] - s38 * v[18] - s39 * v[19];
        w[20] = s40 * v[12] + s41 * v[13] - s40 * v[18] - s41 * v[19];
        w[21] = s42 * v[16] + s43 * v[17] - s42 * v[20] - s43 * v[21];
        w[22] = s44 * v[18] + s45 * v[19] - s44 * v[22] - s45 * v[23];
        w[23] = s46 * v[16] + s47 * v[17] - s46 * v[22] - s47 * v[23];
        w[24] = s48 * v[20] + s49 * v[21] - s48 * v[24] - s49 * v[25];
        w[25] = s50 * v[22] + s51 * v[23] - s50 * v[26] - s51 * v[27];
        w[26] = s52 * v[20] + s53 * v[21] - s52 * v[26] - s53 * v[27];
        w[27] = s54 * v[24] + s55 * v[25] - s54 * v[28] - s55 * v[29];
        w[28] = s56 * v[26] + s57 * v[27] - s56 * v[30] - s57 * v[31];
        w[29] = s58 * v[24] + s59 * v[25] - s58 * v[30] - s59 * v[31];
        w[30] = s60 * v[28] + s61 * v[29] - s60 * v[32] - s61 * v[33];
        w[31] = s62 * v[30] + s63 * v[31] - s62 * v[34] - s63 * v[35];
        w[32] = s64 * v[28] + s65 * v[29] - s64 * v[34] - s65 * v[35];
        w[33] = v[0];
        w[34] = v[1];
        w[35] = v[32];
        w[36] = v[33];
        w
    }
    #[inline]
    fn constraint_acceleration_bias(
        &self,
        q: &::zeitner::__private::Vector<36>,
        v: &::zeitner::__private::Vector<36>,
        t: ::zeitner::__private::Float,
    ) -> ::zeitner::__private::Vector<37> {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let s0 = 2.0 * v[0];
        let s1 = 2.0 * v[2];
        let s2 = 2.0 * v[1];
        let s3 = 2.0 * v[3];
        let s4 = -2.0 * v[0];
        let s5 = -2.0 * v[2];
        let s6 = -2.0 * v[1];
        let s7 = -2.0 * v[3];
        let s8 = 2.0 * v[4];
        let s9 = 2.0 * v[6];
        let s10 = 2.0 * v[5];
        let s11 = 2.0 * v[7];
        let s12 = -2.0 * v[4];
        let s13 = -2.0 * v[6];
        let s14 = -2.0 * v[5];
        let s15 = -2.0 * v[7];
        let s16 = 2.0 * v[8];
        let s17 = 2.0 * v[10];
        let s18 = 2.0 * v[9];
        let s19 = 2.0 * v[11];
        let s20 = -2.0 * v[8];
        let s21 = -2.0 * v[10];
        let s22 = -2.0 * v[9];
        let s23 = -2.0 * v[11];
        let s24 = 2.0 * v[12];
        let s25 = 2.0 * v[14];
        let s26 = 2.0 * v[13];
        let s27 = 2.0 * v[15];
        let s28 = -2.0 * v[12];
        let s29 = -2.0 * v[14];
        let s30 = -2.0 * v[13];
        let s31 = -2.0 * v[15];
        let s32 = 2.0 * v[16];
        let s33 = 2.0 * v[18];
        let s34 = 2.0 * v[17];
        let s35 = 2.0 * v[19];
        let s36 = -2.0 * v[16];
        let s37 = -2.0 * v[18];
        let s38 = -2.0 * v[17];
        let s39 = -2.0 * v[19];
        let s40 = 2.0 * v[20];
        let s41 = 2.0 * v[22];
        let s42 = 2.0 * v[21];
        let s43 = 2.0 * v[23];
        let s44 = -2.0 * v[20];
        let s45 = -2.0 * v[22];
        let s46 = -2.0 * v[21];
        let s47 = -2.0 * v[23];
        let s48 = 2.0 * v[24];
        let s49 = 2.0 * v[26];
        let s50 = 2.0 * v[25];
        let s51 = 2.0 * v[27];
        let s52 = -2.0 * v[24];
        let s53 = -2.0 * v[26];
        let s54 = -2.0 * v[25];
        let s55 = -2.0 * v[27];
        let s56 = 2.0 * v[28];
        let s57 = 2.0 * v[30];
        let s58 = 2.0 * v[29];
        let s59 = 2.0 * v[31];
        let s60 = -2.0 * v[28];
        let s61 = -2.0 * v[30];
        let s62 = -2.0 * v[29];
        let s63 = -2.0 * v[31];
        let s64 = 2.0 * v[32];
        let s65 = 2.0 * v[34];
        let s66 = 2.0 * v[33];
        let s67 = 2.0 * v[35];
        let s68 = -2.0 * v[32];
        let s69 = -2.0 * v[34];
        let s70 = -2.0 * v[33];
        let s71 = -2.0 * v[35];
        let mut b = ::zeitner::__private::Vector::<37>::zeros();
        b[0] = v[0] * (s0 - s1) + v[1] * (s2 - s3) + v[2] * (s4 - s5) + v[3] * (s6 - s7);
        b[1] = v[4] * (s8 - s9) + v[5] * (s10 - s11) + v[6] * (s12 - s13)
            + v[7] * (s14 - s15);
        b[2] = v[8] * (s16 - s17) + v[9] * (s18 - s19) + v[10] * (s20 - s21)
            + v[11] * (s22 - s23);
        b[3] = v[12] * (s24 - s25) + v[13] * (s26 - s27) + v[14] * (s28 - s29)
            + v[15] * (s30 - s31);
        b[4] = v[16] * (s32 - s33) + v[17] * (s34 - s35) + v[18] * (s36 - s37)
            + v[19] * (s38 - s39);
        b[5] = v[20] * (s40 - s41) + v[21] * (s42 - s43) + v[22] * (s44 - s45)
            + v[23] * (s46 - s47);
        b[6] = v[24] * (s48 - s49) + v[25] * (s50 - s51) + v[26] * (s52 - s53)
            + v[27] * (s54 - s55);
        b[7] = v[28] * (s56 - s57) + v[29] * (s58 - s59) + v[30] * (s60 - s61)
            + v[31] * (s62 - s63);
        b[8] = v[32] * (s64 - s65) + v[33] * (s66 - s67) + v[34] * (s68 - s69)
            + v[35] * (s70 - s71);
        b[9] = v[0] * (s0 - s8) + v[1] * (s2 - s10) + v[4] * (s4 - s12)
            + v[5] * (s6 - s14);
        b[10] = v[2] * (s1 - s9) + v[3] * (s3 - s11) + v[6] * (s5 - s13)
            + v[7] * (s7 - s15);
        b[11] = v[0] * (s0 - s9) + v[1] * (s2 - s11) + v[6] * (s4 - s13)
            + v[7] * (s6 - s15);
        b[12] = v[4] * (s8 - s16) + v[5] * (s10 - s18) + v[8] * (s12 - s20)
            + v[9] * (s14 - s22);
        b[13] = v[6] * (s9 - s17) + v[7] * (s11 - s19) + v[10] * (s13 - s21)
            + v[11] * (s15 - s23);
        b[14] = v[4] * (s8 - s17) + v[5] * (s10 - s19) + v[10] * (s12 - s21)
            + v[11] * (s14 - s23);
        b[15] = v[8] * (s16 - s24) + v[9] * (s18 - s26) + v[12] * (s20 - s28)
            + v[13] * (s22 - s30);
        b[16] = v[10] * (s17 - s25) + v[11] * (s19 - s27) + v[14] * (s21 - s29)
            + v[15] * (s23 - s31);
        b[17] = v[8] * (s16 - s25) + v[9] * (s18 - s27) + v[14] * (s20 - s29)
            + v[15] * (s22 - s31);
        b[18] = v[12] * (s24 - s32) + v[13] * (s26 - s34) + v[16] * (s28 - s36)
            + v[17] * (s30 - s38);
        b[19] = v[14] * (s25 - s33) + v[15] * (s27 - s35) + v[18] * (s29 - s37)
            + v[19] * (s31 - s39);
        b[20] = v[12] * (s24 - s33) + v[13] * (s26 - s35) + v[18] * (s28 - s37)
            + v[19] * (s30 - s39);
        b[21] = v[16] * (s32 - s40) + v[17] * (s34 - s42) + v[20] * (s36 - s44)
            + v[21] * (s38 - s46);
        b[22] = v[18] * (s33 - s41) + v[19] * (s35 - s43) + v[22] * (s37 - s45)
            + v[23] * (s39 - s47);
        b[23] = v[16] * (s32 - s41) + v[17] * (s34 - s43) + v[22] * (s36 - s45)
            + v[23] * (s38 - s47);
        b[24] = v[20] * (s40 - s48) + v[21] * (s42 - s50) + v[24] * (s44 - s52)
            + v[25] * (s46 - s54);
        b[25] = v[22] * (s41 - s49) + v[23] * (s43 - s51) + v[26] * (s45 - s53)
            + v[27] * (s47 - s55);
        b[26] = v[20] * (s40 - s49) + v[21] * (s42 - s51) + v[26] * (s44 - s53)
            + v[27] * (s46 - s55);
        b[27] = v[24] * (s48 - s56) + v[25] * (s50 - s58) + v[28] * (s52 - s60)
            + v[29] * (s54 - s62);
        b[28] = v[26] * (s49 - s57) + v[27] * (s51 - s59) + v[30] * (s53 - s61)
            + v[31] * (s55 - s63);
        b[29] = v[24] * (s48 - s57) + v[25] * (s50 - s59) + v[30] * (s52 - s61)
            + v[31] * (s54 - s63);
        b[30] = v[28] * (s56 - s64) + v[29] * (s58 - s66) + v[32] * (s60 - s68)
            + v[33] * (s62 - s70);
        b[31] = v[30] * (s57 - s65) + v[31] * (s59 - s67) + v[34] * (s61 - s69)
            + v[35] * (s63 - s71);
        b[32] = v[28] * (s56 - s65) + v[29] * (s58 - s67) + v[34] * (s60 - s69)
            + v[35] * (s62 - s71);
        b
    }
    #[inline]
    fn stage(
        &self,
        q: &::zeitner::__private::Vector<36>,
        v: &::zeitner::__private::Vector<36>,
        t: ::zeitner::__private::Float,
    ) -> (
        Self::Mass,
        ::zeitner::__private::Vector<36>,
        ::zeitner::__private::Matrix<37, 36>,
        ::zeitner::__private::Vector<37>,
    ) {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let s0 = -(self.m * self.g);
        let s1 = 2.0 * (q[0] - q[2]);
        let s2 = 2.0 * (q[1] - q[3]);
        let s3 = 2.0 * (q[4] - q[6]);
        let s4 = 2.0 * (q[5] - q[7]);
        let s5 = 2.0 * (q[8] - q[10]);
        let s6 = 2.0 * (q[9] - q[11]);
        let s7 = 2.0 * (q[12] - q[14]);
        let s8 = 2.0 * (q[13] - q[15]);
        let s9 = 2.0 * (q[16] - q[18]);
        let s10 = 2.0 * (q[17] - q[19]);
        let s11 = 2.0 * (q[20] - q[22]);
        let s12 = 2.0 * (q[21] - q[23]);
        let s13 = 2.0 * (q[24] - q[26]);
        let s14 = 2.0 * (q[25] - q[27]);
        let s15 = 2.0 * (q[28] - q[30]);
        let s16 = 2.0 * (q[29] - q[31]);
        let s17 = 2.0 * (q[32] - q[34]);
        let s18 = 2.0 * (q[33] - q[35]);
        let s19 = 2.0 * (q[0] - q[4]);
        let s20 = 2.0 * (q[1] - q[5]);
        let s21 = 2.0 * (q[2] - q[6]);
        let s22 = 2.0 * (q[3] - q[7]);
        let s23 = 2.0 * (q[0] - q[6]);
        let s24 = 2.0 * (q[1] - q[7]);
        let s25 = 2.0 * (q[4] - q[8]);
        let s26 = 2.0 * (q[5] - q[9]);
        let s27 = 2.0 * (q[6] - q[10]);
        let s28 = 2.0 * (q[7] - q[11]);
        let s29 = 2.0 * (q[4] - q[10]);
        let s30 = 2.0 * (q[5] - q[11]);
        let s31 = 2.0 * (q[8] - q[12]);
        let s32 = 2.0 * (q[9] - q[13]);
        let s33 = 2.0 * (q[10] - q[14]);
        let s34 = 2.0 * (q[11] - q[15]);
        let s35 = 2.0 * (q[8] - q[14]);
        let s36 = 2.0 * (q[9] - q[15]);
        let s37 = 2.0 * (q[12] - q[16]);
        let s38 = 2.0 * (q[13] - q[17]);
        let s39 = 2.0 * (q[14] - q[18]);
        let s40 = 2.0 * (q[15] - q[19]);
        let s41 = 2.0 * (q[12] - q[18]);
        let s42 = 2.0 * (q[13] - q[19]);
        let s43 = 2.0 * (q[16] - q[20]);
        let s44 = 2.0 * (q[17] - q[21]);
        let s45 = 2.0 * (q[18] - q[22]);
        let s46 = 2.0 * (q[19] - q[23]);
        let s47 = 2.0 * (q[16] - q[22]);
        let s48 = 2.0 * (q[17] - q[23]);
        let s49 = 2.0 * (q[20] - q[24]);
        let s50 = 2.0 * (q[21] - q[25]);
        let s51 = 2.0 * (q[22] - q[26]);
        let s52 = 2.0 * (q[23] - q[27]);
        let s53 = 2.0 * (q[20] - q[26]);
        let s54 = 2.0 * (q[21] - q[27]);
        let s55 = 2.0 * (q[24] - q[28]);
        let s56 = 2.0 * (q[25] - q[29]);
        let s57 = 2.0 * (q[26] - q[30]);
        let s58 = 2.0 * (q[27] - q[31]);
        let s59 = 2.0 * (q[24] - q[30]);
        let s60 = 2.0 * (q[25] - q[31]);
        let s61 = 2.0 * (q[28] - q[32]);
        let s62 = 2.0 * (q[29] - q[33]);
        let s63 = 2.0 * (q[30] - q[34]);
        let s64 = 2.0 * (q[31] - q[35]);
        let s65 = 2.0 * (q[28] - q[34]);
        let s66 = 2.0 * (q[29] - q[35]);
        let s67 = 2.0 * v[0];
        let s68 = 2.0 * v[2];
        let s69 = 2.0 * v[1];
        let s70 = 2.0 * v[3];
        let s71 = -2.0 * v[0];
        let s72 = -2.0 * v[2];
        let s73 = -2.0 * v[1];
        let s74 = -2.0 * v[3];
        let s75 = 2.0 * v[4];
        let s76 = 2.0 * v[6];
        let s77 = 2.0 * v[5];
        let s78 = 2.0 * v[7];
        let s79 = -2.0 * v[4];
        let s80 = -2.0 * v[6];
        let s81 = -2.0 * v[5];
        let s82 = -2.0 * v[7];
        let s83 = 2.0 * v[8];
        let s84 = 2.0 * v[10];
        let s85 = 2.0 * v[9];
        let s86 = 2.0 * v[11];
        let s87 = -2.0 * v[8];
        let s88 = -2.0 * v[10];
        let s89 = -2.0 * v[9];
        let s90 = -2.0 * v[11];
        let s91 = 2.0 * v[12];
        let s92 = 2.0 * v[14];
        let s93 = 2.0 * v[13];
        let s94 = 2.0 * v[15];
        let s95 = -2.0 * v[12];
        let s96 = -2.0 * v[14];
        let s97 = -2.0 * v[13];
        let s98 = -2.0 * v[15];
        let s99 = 2.0 * v[16];
        let s100 = 2.0 * v[18];
        let s101 = 2.0 * v[17];
        let s102 = 2.0 * v[19];
        let s103 = -2.0 * v[16];
        let s104 = -2.0 * v[18];
        let s105 = -2.0 * v[17];
        let s106 = -2.0 * v[19];
        let s107 = 2.0 * v[20];
        let s108 = 2.0 * v[22];
        let s109 = 2.0 * v[21];
        let s110 = 2.0 * v[23];
        let s111 = -2.0 * v[20];
        let s112 = -2.0 * v[22];
        let s113 = -2.0 * v[21];
        let s114 = -2.0 * v[23];
        let s115 = 2.0 * v[24];
        let s116 = 2.0 * v[26];
        let s117 = 2.0 * v[25];
        let s118 = 2.0 * v[27];
        let s119 = -2.0 * v[24];
        let s120 = -2.0 * v[26];
        let s121 = -2.0 * v[25];
        let s122 = -2.0 * v[27];
        let s123 = 2.0 * v[28];
        let s124 = 2.0 * v[30];
        let s125 = 2.0 * v[29];
        let s126 = 2.0 * v[31];
        let s127 = -2.0 * v[28];
        let s128 = -2.0 * v[30];
        let s129 = -2.0 * v[29];
        let s130 = -2.0 * v[31];
        let s131 = 2.0 * v[32];
        let s132 = 2.0 * v[34];
        let s133 = 2.0 * v[33];
        let s134 = 2.0 * v[35];
        let s135 = -2.0 * v[32];
        let s136 = -2.0 * v[34];
        let s137 = -2.0 * v[33];
        let s138 = -2.0 * v[35];
        let mut m = ::zeitner::__private::Vector::<36>::zeros();
        let mut f = ::zeitner::__private::Vector::<36>::zeros();
        let mut g = ::zeitner::__private::Matrix::<37, 36>::zeros();
        let mut b = ::zeitner::__private::Vector::<37>::zeros();
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
        g[(0, 0)] = s1;
        g[(0, 1)] = s2;
        g[(0, 2)] = -s1;
        g[(0, 3)] = -s2;
        g[(1, 4)] = s3;
        g[(1, 5)] = s4;
        g[(1, 6)] = -s3;
        g[(1, 7)] = -s4;
        g[(2, 8)] = s5;
        g[(2, 9)] = s6;
        g[(2, 10)] = -s5;
        g[(2, 11)] = -s6;
        g[(3, 12)] = s7;
        g[(3, 13)] = s8;
        g[(3, 14)] = -s7;
        g[(3, 15)] = -s8;
        g[(4, 16)] = s9;
        g[(4, 17)] = s10;
        g[(4, 18)] = -s9;
        g[(4, 19)] = -s10;
        g[(5, 20)] = s11;
        g[(5, 21)] = s12;
        g[(5, 22)] = -s11;
        g[(5, 23)] = -s12;
        g[(6, 24)] = s13;
        g[(6, 25)] = s14;
        g[(6, 26)] = -s13;
        g[(6, 27)] = -s14;
        g[(7, 28)] = s15;
        g[(7, 29)] = s16;
        g[(7, 30)] = -s15;
        g[(7, 31)] = -s16;
        g[(8, 32)] = s17;
        g[(8, 33)] = s18;
        g[(8, 34)] = -s17;
        g[(8, 35)] = -s18;
        g[(9, 0)] = s19;
        g[(9, 1)] = s20;
        g[(9, 4)] = -s19;
        g[(9, 5)] = -s20;
        g[(10, 2)] = s21;
        g[(10, 3)] = s22;
        g[(10, 6)] = -s21;
        g[(10, 7)] = -s22;
        g[(11, 0)] = s23;
        g[(11, 1)] = s24;
        g[(11, 6)] = -s23;
        g[(11, 7)] = -s24;
        g[(12, 4)] = s25;
        g[(12, 5)] = s26;
        g[(12, 8)] = -s25;
        g[(12, 9)] = -s26;
        g[(13, 6)] = s27;
        g[(13, 7)] = s28;
        g[(13, 10)] = -s27;
        g[(13, 11)] = -s28;
        g[(14, 4)] = s29;
        g[(14, 5)] = s30;
        g[(14, 10)] = -s29;
        g[(14, 11)] = -s30;
        g[(15, 8)] = s31;
        g[(15, 9)] = s32;
        g[(15, 12)] = -s31;
        g[(15, 13)] = -s32;
        g[(16, 10)] = s33;
        g[(16, 11)] = s34;
        g[(16, 14)] = -s33;
        g[(16, 15)] = -s34;
        g[(17, 8)] = s35;
        g[(17, 9)] = s36;
        g[(17, 14)] = -s35;
        g[(17, 15)] = -s36;
        g[(18, 12)] = s37;
        g[(18, 13)] = s38;
        g[(18, 16)] = -s37;
        g[(18, 17)] = -s38;
        g[(19, 14)] = s39;
        g[(19, 15)] = s40;
        g[(19, 18)] = -s39;
        g[(19, 19)] = -s40;
        g[(20, 12)] = s41;
        g[(20, 13)] = s42;
        g[(20, 18)] = -s41;
        g[(20, 19)] = -s42;
        g[(21, 16)] = s43;
        g[(21, 17)] = s44;
        g[(21, 20)] = -s43;
        g[(21, 21)] = -s44;
        g[(22, 18)] = s45;
        g[(22, 19)] = s46;
        g[(22, 22)] = -s45;
        g[(22, 23)] = -s46;
        g[(23, 16)] = s47;
        g[(23, 17)] = s48;
        g[(23, 22)] = -s47;
        g[(23, 23)] = -s48;
        g[(24, 20)] = s49;
        g[(24, 21)] = s50;
        g[(24, 24)] = -s49;
        g[(24, 25)] = -s50;
        g[(25, 22)] = s51;
        g[(25, 23)] = s52;
        g[(25, 26)] = -s51;
        g[(25, 27)] = -s52;
        g[(26, 20)] = s53;
        g[(26, 21)] = s54;
        g[(26, 26)] = -s53;
        g[(26, 27)] = -s54;
        g[(27, 24)] = s55;
        g[(27, 25)] = s56;
        g[(27, 28)] = -s55;
        g[(27, 29)] = -s56;
        g[(28, 26)] = s57;
        g[(28, 27)] = s58;
        g[(28, 30)] = -s57;
        g[(28, 31)] = -s58;
        g[(29, 24)] = s59;
        g[(29, 25)] = s60;
        g[(29, 30)] = -s59;
        g[(29, 31)] = -s60;
        g[(30, 28)] = s61;
        g[(30, 29)] = s62;
        g[(30, 32)] = -s61;
        g[(30, 33)] = -s62;
        g[(31, 30)] = s63;
        g[(31, 31)] = s64;
        g[(31, 34)] = -s63;
        g[(31, 35)] = -s64;
        g[(32, 28)] = s65;
        g[(32, 29)] = s66;
        g[(32, 34)] = -s65;
        g[(32, 35)] = -s66;
        g[(33, 0)] = 1.0;
        g[(34, 1)] = 1.0;
        g[(35, 32)] = 1.0;
        g[(36, 33)] = 1.0;
        b[0] = v[0] * (s67 - s68) + v[1] * (s69 - s70) + v[2] * (s71 - s72)
            + v[3] * (s73 - s74);
        b[1] = v[4] * (s75 - s76) + v[5] * (s77 - s78) + v[6] * (s79 - s80)
            + v[7] * (s81 - s82);
        b[2] = v[8] * (s83 - s84) + v[9] * (s85 - s86) + v[10] * (s87 - s88)
            + v[11] * (s89 - s90);
        b[3] = v[12] * (s91 - s92) + v[13] * (s93 - s94) + v[14] * (s95 - s96)
            + v[15] * (s97 - s98);
        b[4] = v[16] * (s99 - s100) + v[17] * (s101 - s102) + v[18] * (s103 - s104)
            + v[19] * (s105 - s106);
        b[5] = v[20] * (s107 - s108) + v[21] * (s109 - s110) + v[22] * (s111 - s112)
            + v[23] * (s113 - s114);
        b[6] = v[24] * (s115 - s116) + v[25] * (s117 - s118) + v[26] * (s119 - s120)
            + v[27] * (s121 - s122);
        b[7] = v[28] * (s123 - s124) + v[29] * (s125 - s126) + v[30] * (s127 - s128)
            + v[31] * (s129 - s130);
        b[8] = v[32] * (s131 - s132) + v[33] * (s133 - s134) + v[34] * (s135 - s136)
            + v[35] * (s137 - s138);
        b[9] = v[0] * (s67 - s75) + v[1] * (s69 - s77) + v[4] * (s71 - s79)
            + v[5] * (s73 - s81);
        b[10] = v[2] * (s68 - s76) + v[3] * (s70 - s78) + v[6] * (s72 - s80)
            + v[7] * (s74 - s82);
        b[11] = v[0] * (s67 - s76) + v[1] * (s69 - s78) + v[6] * (s71 - s80)
            + v[7] * (s73 - s82);
        b[12] = v[4] * (s75 - s83) + v[5] * (s77 - s85) + v[8] * (s79 - s87)
            + v[9] * (s81 - s89);
        b[13] = v[6] * (s76 - s84) + v[7] * (s78 - s86) + v[10] * (s80 - s88)
            + v[11] * (s82 - s90);
        b[14] = v[4] * (s75 - s84) + v[5] * (s77 - s86) + v[10] * (s79 - s88)
            + v[11] * (s81 - s90);
        b[15] = v[8] * (s83 - s91) + v[9] * (s85 - s93) + v[12] * (s87 - s95)
            + v[13] * (s89 - s97);
        b[16] = v[10] * (s84 - s92) + v[11] * (s86 - s94) + v[14] * (s88 - s96)
            + v[15] * (s90 - s98);
        b[17] = v[8] * (s83 - s92) + v[9] * (s85 - s94) + v[14] * (s87 - s96)
            + v[15] * (s89 - s98);
        b[18] = v[12] * (s91 - s99) + v[13] * (s93 - s101) + v[16] * (s95 - s103)
            + v[17] * (s97 - s105);
        b[19] = v[14] * (s92 - s100) + v[15] * (s94 - s102) + v[18] * (s96 - s104)
            + v[19] * (s98 - s106);
        b[20] = v[12] * (s91 - s100) + v[13] * (s93 - s102) + v[18] * (s95 - s104)
            + v[19] * (s97 - s106);
        b[21] = v[16] * (s99 - s107) + v[17] * (s101 - s109) + v[20] * (s103 - s111)
            + v[21] * (s105 - s113);
        b[22] = v[18] * (s100 - s108) + v[19] * (s102 - s110) + v[22] * (s104 - s112)
            + v[23] * (s106 - s114);
        b[23] = v[16] * (s99 - s108) + v[17] * (s101 - s110) + v[22] * (s103 - s112)
            + v[23] * (s105 - s114);
        b[24] = v[20] * (s107 - s115) + v[21] * (s109 - s117) + v[24] * (s111 - s119)
            + v[25] * (s113 - s121);
        b[25] = v[22] * (s108 - s116) + v[23] * (s110 - s118) + v[26] * (s112 - s120)
            + v[27] * (s114 - s122);
        b[26] = v[20] * (s107 - s116) + v[21] * (s109 - s118) + v[26] * (s111 - s120)
            + v[27] * (s113 - s122);
        b[27] = v[24] * (s115 - s123) + v[25] * (s117 - s125) + v[28] * (s119 - s127)
            + v[29] * (s121 - s129);
        b[28] = v[26] * (s116 - s124) + v[27] * (s118 - s126) + v[30] * (s120 - s128)
            + v[31] * (s122 - s130);
        b[29] = v[24] * (s115 - s124) + v[25] * (s117 - s126) + v[30] * (s119 - s128)
            + v[31] * (s121 - s130);
        b[30] = v[28] * (s123 - s131) + v[29] * (s125 - s133) + v[32] * (s127 - s135)
            + v[33] * (s129 - s137);
        b[31] = v[30] * (s124 - s132) + v[31] * (s126 - s134) + v[34] * (s128 - s136)
            + v[35] * (s130 - s138);
        b[32] = v[28] * (s123 - s132) + v[29] * (s125 - s134) + v[34] * (s127 - s136)
            + v[35] * (s129 - s138);
        (::zeitner::__private::DiagonalMass(m), f, g, b)
    }
    #[inline]
    fn force_jacobians(
        &self,
        q: &::zeitner::__private::Vector<36>,
        v: &::zeitner::__private::Vector<36>,
        t: ::zeitner::__private::Float,
    ) -> (::zeitner::__private::Matrix<36, 36>, ::zeitner::__private::Matrix<36, 36>) {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let mut dq = ::zeitner::__private::Matrix::<36, 36>::zeros();
        let mut dv = ::zeitner::__private::Matrix::<36, 36>::zeros();
        (dq, dv)
    }
    #[inline]
    fn constraint_force_jacobians(
        &self,
        q: &::zeitner::__private::Vector<36>,
        v: &::zeitner::__private::Vector<36>,
        t: ::zeitner::__private::Float,
        lambda: &::zeitner::__private::Vector<37>,
    ) -> (::zeitner::__private::Matrix<36, 36>, ::zeitner::__private::Matrix<36, 36>) {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let s0 = 2.0 * lambda[0];
        let s1 = 2.0 * lambda[9];
        let s2 = 2.0 * lambda[11];
        let s3 = s0 + s1 + s2;
        let s4 = -2.0 * lambda[0];
        let s5 = -2.0 * lambda[9];
        let s6 = -2.0 * lambda[11];
        let s7 = -s0;
        let s8 = 2.0 * lambda[10];
        let s9 = s8 - s4;
        let s10 = -2.0 * lambda[10];
        let s11 = -s1;
        let s12 = 2.0 * lambda[1];
        let s13 = 2.0 * lambda[12];
        let s14 = 2.0 * lambda[14];
        let s15 = s12 - s5 + s13 + s14;
        let s16 = -2.0 * lambda[1];
        let s17 = -2.0 * lambda[12];
        let s18 = -2.0 * lambda[14];
        let s19 = -s2;
        let s20 = -s8;
        let s21 = -s12;
        let s22 = 2.0 * lambda[13];
        let s23 = -s16 - s10 - s6 + s22;
        let s24 = -2.0 * lambda[13];
        let s25 = -s13;
        let s26 = 2.0 * lambda[2];
        let s27 = 2.0 * lambda[15];
        let s28 = 2.0 * lambda[17];
        let s29 = s26 - s17 + s27 + s28;
        let s30 = -2.0 * lambda[2];
        let s31 = -2.0 * lambda[15];
        let s32 = -2.0 * lambda[17];
        let s33 = -s14;
        let s34 = -s22;
        let s35 = -s26;
        let s36 = 2.0 * lambda[16];
        let s37 = -s30 - s24 - s18 + s36;
        let s38 = -2.0 * lambda[16];
        let s39 = -s27;
        let s40 = 2.0 * lambda[3];
        let s41 = 2.0 * lambda[18];
        let s42 = 2.0 * lambda[20];
        let s43 = s40 - s31 + s41 + s42;
        let s44 = -2.0 * lambda[3];
        let s45 = -2.0 * lambda[18];
        let s46 = -2.0 * lambda[20];
        let s47 = -s28;
        let s48 = -s36;
        let s49 = -s40;
        let s50 = 2.0 * lambda[19];
        let s51 = -s44 - s38 - s32 + s50;
        let s52 = -2.0 * lambda[19];
        let s53 = -s41;
        let s54 = 2.0 * lambda[4];
        let s55 = 2.0 * lambda[21];
        let s56 = 2.0 * lambda[23];
        let s57 = s54 - s45 + s55 + s56;
        let s58 = -2.0 * lambda[4];
        let s59 = -2.0 * lambda[21];
        let s60 = -2.0 * lambda[23];
        let s61 = -s42;
        let s62 = -s50;
        let s63 = -s54;
        let s64 = 2.0 * lambda[22];
        let s65 = -s58 - s52 - s46 + s64;
        let s66 = -2.0 * lambda[22];
        let s67 = -s55;
        let s68 = 2.0 * lambda[5];
        let s69 = 2.0 * lambda[24];
        let s70 = 2.0 * lambda[26];
        let s71 = s68 - s59 + s69 + s70;
        let s72 = -2.0 * lambda[5];
        let s73 = -2.0 * lambda[24];
        let s74 = -2.0 * lambda[26];
        let s75 = -s56;
        let s76 = -s64;
        let s77 = -s68;
        let s78 = 2.0 * lambda[25];
        let s79 = -s72 - s66 - s60 + s78;
        let s80 = -2.0 * lambda[25];
        let s81 = -s69;
        let s82 = 2.0 * lambda[6];
        let s83 = 2.0 * lambda[27];
        let s84 = 2.0 * lambda[29];
        let s85 = s82 - s73 + s83 + s84;
        let s86 = -2.0 * lambda[6];
        let s87 = -2.0 * lambda[27];
        let s88 = -2.0 * lambda[29];
        let s89 = -s70;
        let s90 = -s78;
        let s91 = -s82;
        let s92 = 2.0 * lambda[28];
        let s93 = -s86 - s80 - s74 + s92;
        let s94 = -2.0 * lambda[28];
        let s95 = -s83;
        let s96 = 2.0 * lambda[7];
        let s97 = 2.0 * lambda[30];
        let s98 = 2.0 * lambda[32];
        let s99 = s96 - s87 + s97 + s98;
        let s100 = -2.0 * lambda[7];
        let s101 = -2.0 * lambda[30];
        let s102 = -2.0 * lambda[32];
        let s103 = -s84;
        let s104 = -s92;
        let s105 = -s96;
        let s106 = 2.0 * lambda[31];
        let s107 = -s100 - s94 - s88 + s106;
        let s108 = -2.0 * lambda[31];
        let s109 = -s97;
        let s110 = 2.0 * lambda[8];
        let s111 = s110 - s101;
        let s112 = -2.0 * lambda[8];
        let s113 = -s98;
        let s114 = -s106;
        let s115 = -s110;
        let s116 = -s112 - s108 - s102;
        let mut dq = ::zeitner::__private::Matrix::<36, 36>::zeros();
        let mut dv = ::zeitner::__private::Matrix::<36, 36>::zeros();
        dq[(0, 0)] = s3;
        dq[(0, 2)] = s4;
        dq[(0, 4)] = s5;
        dq[(0, 6)] = s6;
        dq[(1, 1)] = s3;
        dq[(1, 3)] = s4;
        dq[(1, 5)] = s5;
        dq[(1, 7)] = s6;
        dq[(2, 0)] = s7;
        dq[(2, 2)] = s9;
        dq[(2, 6)] = s10;
        dq[(3, 1)] = s7;
        dq[(3, 3)] = s9;
        dq[(3, 7)] = s10;
        dq[(4, 0)] = s11;
        dq[(4, 4)] = s15;
        dq[(4, 6)] = s16;
        dq[(4, 8)] = s17;
        dq[(4, 10)] = s18;
        dq[(5, 1)] = s11;
        dq[(5, 5)] = s15;
        dq[(5, 7)] = s16;
        dq[(5, 9)] = s17;
        dq[(5, 11)] = s18;
        dq[(6, 0)] = s19;
        dq[(6, 2)] = s20;
        dq[(6, 4)] = s21;
        dq[(6, 6)] = s23;
        dq[(6, 10)] = s24;
        dq[(7, 1)] = s19;
        dq[(7, 3)] = s20;
        dq[(7, 5)] = s21;
        dq[(7, 7)] = s23;
        dq[(7, 11)] = s24;
        dq[(8, 4)] = s25;
        dq[(8, 8)] = s29;
        dq[(8, 10)] = s30;
        dq[(8, 12)] = s31;
        dq[(8, 14)] = s32;
        dq[(9, 5)] = s25;
        dq[(9, 9)] = s29;
        dq[(9, 11)] = s30;
        dq[(9, 13)] = s31;
        dq[(9, 15)] = s32;
        dq[(10, 4)] = s33;
        dq[(10, 6)] = s34;
        dq[(10, 8)] = s35;
        dq[(10, 10)] = s37;
        dq[(10, 14)] = s38;
        dq[(11, 5)] = s33;
        dq[(11, 7)] = s34;
        dq[(11, 9)] = s35;
        dq[(11, 11)] = s37;
        dq[(11, 15)] = s38;
        dq[(12, 8)] = s39;
        dq[(12, 12)] = s43;
        dq[(12, 14)] = s44;
        dq[(12, 16)] = s45;
        dq[(12, 18)] = s46;
        dq[(13, 9)] = s39;
        dq[(13, 13)] = s43;
        dq[(13, 15)] = s44;
        dq[(13, 17)] = s45;
        dq[(13, 19)] = s46;
        dq[(14, 8)] = s47;
        dq[(14, 10)] = s48;
        dq[(14, 12)] = s49;
        dq[(14, 14)] = s51;
        dq[(14, 18)] = s52;
        dq[(15, 9)] = s47;
        dq[(15, 11)] = s48;
        dq[(15, 13)] = s49;
        dq[(15, 15)] = s51;
        dq[(15, 19)] = s52;
        dq[(16, 12)] = s53;
        dq[(16, 16)] = s57;
        dq[(16, 18)] = s58;
        dq[(16, 20)] = s59;
        dq[(16, 22)] = s60;
        dq[(17, 13)] = s53;
        dq[(17, 17)] = s57;
        dq[(17, 19)] = s58;
        dq[(17, 21)] = s59;
        dq[(17, 23)] = s60;
        dq[(18, 12)] = s61;
        dq[(18, 14)] = s62;
        dq[(18, 16)] = s63;
        dq[(18, 18)] = s65;
        dq[(18, 22)] = s66;
        dq[(19, 13)] = s61;
        dq[(19, 15)] = s62;
        dq[(19, 17)] = s63;
        dq[(19, 19)] = s65;
        dq[(19, 23)] = s66;
        dq[(20, 16)] = s67;
        dq[(20, 20)] = s71;
        dq[(20, 22)] = s72;
        dq[(20, 24)] = s73;
        dq[(20, 26)] = s74;
        dq[(21, 17)] = s67;
        dq[(21, 21)] = s71;
        dq[(21, 23)] = s72;
        dq[(21, 25)] = s73;
        dq[(21, 27)] = s74;
        dq[(22, 16)] = s75;
        dq[(22, 18)] = s76;
        dq[(22, 20)] = s77;
        dq[(22, 22)] = s79;
        dq[(22, 26)] = s80;
        dq[(23, 17)] = s75;
        dq[(23, 19)] = s76;
        dq[(23, 21)] = s77;
        dq[(23, 23)] = s79;
        dq[(23, 27)] = s80;
        dq[(24, 20)] = s81;
        dq[(24, 24)] = s85;
        dq[(24, 26)] = s86;
        dq[(24, 28)] = s87;
        dq[(24, 30)] = s88;
        dq[(25, 21)] = s81;
        dq[(25, 25)] = s85;
        dq[(25, 27)] = s86;
        dq[(25, 29)] = s87;
        dq[(25, 31)] = s88;
        dq[(26, 20)] = s89;
        dq[(26, 22)] = s90;
        dq[(26, 24)] = s91;
        dq[(26, 26)] = s93;
        dq[(26, 30)] = s94;
        dq[(27, 21)] = s89;
        dq[(27, 23)] = s90;
        dq[(27, 25)] = s91;
        dq[(27, 27)] = s93;
        dq[(27, 31)] = s94;
        dq[(28, 24)] = s95;
        dq[(28, 28)] = s99;
        dq[(28, 30)] = s100;
        dq[(28, 32)] = s101;
        dq[(28, 34)] = s102;
        dq[(29, 25)] = s95;
        dq[(29, 29)] = s99;
        dq[(29, 31)] = s100;
        dq[(29, 33)] = s101;
        dq[(29, 35)] = s102;
        dq[(30, 24)] = s103;
        dq[(30, 26)] = s104;
        dq[(30, 28)] = s105;
        dq[(30, 30)] = s107;
        dq[(30, 34)] = s108;
        dq[(31, 25)] = s103;
        dq[(31, 27)] = s104;
        dq[(31, 29)] = s105;
        dq[(31, 31)] = s107;
        dq[(31, 35)] = s108;
        dq[(32, 28)] = s109;
        dq[(32, 32)] = s111;
        dq[(32, 34)] = s112;
        dq[(33, 29)] = s109;
        dq[(33, 33)] = s111;
        dq[(33, 35)] = s112;
        dq[(34, 28)] = s113;
        dq[(34, 30)] = s114;
        dq[(34, 32)] = s115;
        dq[(34, 34)] = s116;
        dq[(35, 29)] = s113;
        dq[(35, 31)] = s114;
        dq[(35, 33)] = s115;
        dq[(35, 35)] = s116;
        (dq, dv)
    }
    #[inline]
    fn constraint_jacobian_nonzeros(
        &self,
        q: &::zeitner::__private::Vector<36>,
        v: &::zeitner::__private::Vector<36>,
        t: ::zeitner::__private::Float,
        values: &mut [::zeitner::__private::Float],
    ) {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let s0 = 2.0 * (q[0] - q[2]);
        let s1 = 2.0 * (q[1] - q[3]);
        let s2 = 2.0 * (q[4] - q[6]);
        let s3 = 2.0 * (q[5] - q[7]);
        let s4 = 2.0 * (q[8] - q[10]);
        let s5 = 2.0 * (q[9] - q[11]);
        let s6 = 2.0 * (q[12] - q[14]);
        let s7 = 2.0 * (q[13] - q[15]);
        let s8 = 2.0 * (q[16] - q[18]);
        let s9 = 2.0 * (q[17] - q[19]);
        let s10 = 2.0 * (q[20] - q[22]);
        let s11 = 2.0 * (q[21] - q[23]);
        let s12 = 2.0 * (q[24] - q[26]);
        let s13 = 2.0 * (q[25] - q[27]);
        let s14 = 2.0 * (q[28] - q[30]);
        let s15 = 2.0 * (q[29] - q[31]);
        let s16 = 2.0 * (q[32] - q[34]);
        let s17 = 2.0 * (q[33] - q[35]);
        let s18 = 2.0 * (q[0] - q[4]);
        let s19 = 2.0 * (q[1] - q[5]);
        let s20 = 2.0 * (q[2] - q[6]);
        let s21 = 2.0 * (q[3] - q[7]);
        let s22 = 2.0 * (q[0] - q[6]);
        let s23 = 2.0 * (q[1] - q[7]);
        let s24 = 2.0 * (q[4] - q[8]);
        let s25 = 2.0 * (q[5] - q[9]);
        let s26 = 2.0 * (q[6] - q[10]);
        let s27 = 2.0 * (q[7] - q[11]);
        let s28 = 2.0 * (q[4] - q[10]);
        let s29 = 2.0 * (q[5] - q[11]);
        let s30 = 2.0 * (q[8] - q[12]);
        let s31 = 2.0 * (q[9] - q[13]);
        let s32 = 2.0 * (q[10] - q[14]);
        let s33 = 2.0 * (q[11] - q[15]);
        let s34 = 2.0 * (q[8] - q[14]);
        let s35 = 2.0 * (q[9] - q[15]);
        let s36 = 2.0 * (q[12] - q[16]);
        let s37 = 2.0 * (q[13] - q[17]);
        let s38 = 2.0 * (q[14] - q[18]);
        let s39 = 2.0 * (q[15] - q[19]);
        let s40 = 2.0 * (q[12] - q[18]);
        let s41 = 2.0 * (q[13] - q[19]);
        let s42 = 2.0 * (q[16] - q[20]);
        let s43 = 2.0 * (q[17] - q[21]);
        let s44 = 2.0 * (q[18] - q[22]);
        let s45 = 2.0 * (q[19] - q[23]);
        let s46 = 2.0 * (q[16] - q[22]);
        let s47 = 2.0 * (q[17] - q[23]);
        let s48 = 2.0 * (q[20] - q[24]);
        let s49 = 2.0 * (q[21] - q[25]);
        let s50 = 2.0 * (q[22] - q[26]);
        let s51 = 2.0 * (q[23] - q[27]);
        let s52 = 2.0 * (q[20] - q[26]);
        let s53 = 2.0 * (q[21] - q[27]);
        let s54 = 2.0 * (q[24] - q[28]);
        let s55 = 2.0 * (q[25] - q[29]);
        let s56 = 2.0 * (q[26] - q[30]);
        let s57 = 2.0 * (q[27] - q[31]);
        let s58 = 2.0 * (q[24] - q[30]);
        let s59 = 2.0 * (q[25] - q[31]);
        let s60 = 2.0 * (q[28] - q[32]);
        let s61 = 2.0 * (q[29] - q[33]);
        let s62 = 2.0 * (q[30] - q[34]);
        let s63 = 2.0 * (q[31] - q[35]);
        let s64 = 2.0 * (q[28] - q[34]);
        let s65 = 2.0 * (q[29] - q[35]);
        values[0] = s0;
        values[1] = s1;
        values[2] = -s0;
        values[3] = -s1;
        values[4] = s2;
        values[5] = s3;
        values[6] = -s2;
        values[7] = -s3;
        values[8] = s4;
        values[9] = s5;
        values[10] = -s4;
        values[11] = -s5;
        values[12] = s6;
        values[13] = s7;
        values[14] = -s6;
        values[15] = -s7;
        values[16] = s8;
        values[17] = s9;
        values[18] = -s8;
        values[19] = -s9;
        values[20] = s10;
        values[21] = s11;
        values[22] = -s10;
        values[23] = -s11;
        values[24] = s12;
        values[25] = s13;
        values[26] = -s12;
        values[27] = -s13;
        values[28] = s14;
        values[29] = s15;
        values[30] = -s14;
        values[31] = -s15;
        values[32] = s16;
        values[33] = s17;
        values[34] = -s16;
        values[35] = -s17;
        values[36] = s18;
        values[37] = s19;
        values[38] = -s18;
        values[39] = -s19;
        values[40] = s20;
        values[41] = s21;
        values[42] = -s20;
        values[43] = -s21;
        values[44] = s22;
        values[45] = s23;
        values[46] = -s22;
        values[47] = -s23;
        values[48] = s24;
        values[49] = s25;
        values[50] = -s24;
        values[51] = -s25;
        values[52] = s26;
        values[53] = s27;
        values[54] = -s26;
        values[55] = -s27;
        values[56] = s28;
        values[57] = s29;
        values[58] = -s28;
        values[59] = -s29;
        values[60] = s30;
        values[61] = s31;
        values[62] = -s30;
        values[63] = -s31;
        values[64] = s32;
        values[65] = s33;
        values[66] = -s32;
        values[67] = -s33;
        values[68] = s34;
        values[69] = s35;
        values[70] = -s34;
        values[71] = -s35;
        values[72] = s36;
        values[73] = s37;
        values[74] = -s36;
        values[75] = -s37;
        values[76] = s38;
        values[77] = s39;
        values[78] = -s38;
        values[79] = -s39;
        values[80] = s40;
        values[81] = s41;
        values[82] = -s40;
        values[83] = -s41;
        values[84] = s42;
        values[85] = s43;
        values[86] = -s42;
        values[87] = -s43;
        values[88] = s44;
        values[89] = s45;
        values[90] = -s44;
        values[91] = -s45;
        values[92] = s46;
        values[93] = s47;
        values[94] = -s46;
        values[95] = -s47;
        values[96] = s48;
        values[97] = s49;
        values[98] = -s48;
        values[99] = -s49;
        values[100] = s50;
        values[101] = s51;
        values[102] = -s50;
        values[103] = -s51;
        values[104] = s52;
        values[105] = s53;
        values[106] = -s52;
        values[107] = -s53;
        values[108] = s54;
        values[109] = s55;
        values[110] = -s54;
        values[111] = -s55;
        values[112] = s56;
        values[113] = s57;
        values[114] = -s56;
        values[115] = -s57;
        values[116] = s58;
        values[117] = s59;
        values[118] = -s58;
        values[119] = -s59;
        values[120] = s60;
        values[121] = s61;
        values[122] = -s60;
        values[123] = -s61;
        values[124] = s62;
        values[125] = s63;
        values[126] = -s62;
        values[127] = -s63;
        values[128] = s64;
        values[129] = s65;
        values[130] = -s64;
        values[131] = -s65;
        values[132] = 1.0;
        values[133] = 1.0;
        values[134] = 1.0;
        values[135] = 1.0;
    }
    #[inline]
    fn force_jacobian_nonzeros(
        &self,
        q: &::zeitner::__private::Vector<36>,
        v: &::zeitner::__private::Vector<36>,
        t: ::zeitner::__private::Float,
        values: &mut [::zeitner::__private::Float],
    ) {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
    }
    #[inline]
    fn constraint_force_jacobian_nonzeros(
        &self,
        q: &::zeitner::__private::Vector<36>,
        v: &::zeitner::__private::Vector<36>,
        t: ::zeitner::__private::Float,
        lambda: &::zeitner::__private::Vector<37>,
        values: &mut [::zeitner::__private::Float],
    ) {
        #[allow(unused_imports)]
        use ::zeitner::__private::Real as _;
        let s0 = 2.0 * lambda[0];
        let s1 = 2.0 * lambda[9];
        let s2 = 2.0 * lambda[11];
        let s3 = s0 + s1 + s2;
        let s4 = -2.0 * lambda[0];
        let s5 = -2.0 * lambda[9];
        let s6 = -2.0 * lambda[11];
        let s7 = -s0;
        let s8 = 2.0 * lambda[10];
        let s9 = s8 - s4;
        let s10 = -2.0 * lambda[10];
        let s11 = -s1;
        let s12 = 2.0 * lambda[1];
        let s13 = 2.0 * lambda[12];
        let s14 = 2.0 * lambda[14];
        let s15 = s12 - s5 + s13 + s14;
        let s16 = -2.0 * lambda[1];
        let s17 = -2.0 * lambda[12];
        let s18 = -2.0 * lambda[14];
        let s19 = -s2;
        let s20 = -s8;
        let s21 = -s12;
        let s22 = 2.0 * lambda[13];
        let s23 = -s16 - s10 - s6 + s22;
        let s24 = -2.0 * lambda[13];
        let s25 = -s13;
        let s26 = 2.0 * lambda[2];
        let s27 = 2.0 * lambda[15];
        let s28 = 2.0 * lambda[17];
        let s29 = s26 - s17 + s27 + s28;
        let s30 = -2.0 * lambda[2];
        let s31 = -2.0 * lambda[15];
        let s32 = -2.0 * lambda[17];
        let s33 = -s14;
        let s34 = -s22;
        let s35 = -s26;
        let s36 = 2.0 * lambda[16];
        let s37 = -s30 - s24 - s18 + s36;
        let s38 = -2.0 * lambda[16];
        let s39 = -s27;
        let s40 = 2.0 * lambda[3];
        let s41 = 2.0 * lambda[18];
        let s42 = 2.0 * lambda[20];
        let s43 = s40 - s31 + s41 + s42;
        let s44 = -2.0 * lambda[3];
        let s45 = -2.0 * lambda[18];
        let s46 = -2.0 * lambda[20];
        let s47 = -s28;
        let s48 = -s36;
        let s49 = -s40;
        let s50 = 2.0 * lambda[19];
        let s51 = -s44 - s38 - s32 + s50;
        let s52 = -2.0 * lambda[19];
        let s53 = -s41;
        let s54 = 2.0 * lambda[4];
        let s55 = 2.0 * lambda[21];
        let s56 = 2.0 * lambda[23];
        let s57 = s54 - s45 + s55 + s56;
        let s58 = -2.0 * lambda[4];
        let s59 = -2.0 * lambda[21];
        let s60 = -2.0 * lambda[23];
        let s61 = -s42;
        let s62 = -s50;
        let s63 = -s54;
        let s64 = 2.0 * lambda[22];
        let s65 = -s58 - s52 - s46 + s64;
        let s66 = -2.0 * lambda[22];
        let s67 = -s55;
        let s68 = 2.0 * lambda[5];
        let s69 = 2.0 * lambda[24];
        let s70 = 2.0 * lambda[26];
        let s71 = s68 - s59 + s69 + s70;
        let s72 = -2.0 * lambda[5];
        let s73 = -2.0 * lambda[24];
        let s74 = -2.0 * lambda[26];
        let s75 = -s56;
        let s76 = -s64;
        let s77 = -s68;
        let s78 = 2.0 * lambda[25];
        let s79 = -s72 - s66 - s60 + s78;
        let s80 = -2.0 * lambda[25];
        let s81 = -s69;
        let s82 = 2.0 * lambda[6];
        let s83 = 2.0 * lambda[27];
        let s84 = 2.0 * lambda[29];
        let s85 = s82 - s73 + s83 + s84;
        let s86 = -2.0 * lambda[6];
        let s87 = -2.0 * lambda[27];
        let s88 = -2.0 * lambda[29];
        let s89 = -s70;
        let s90 = -s78;
        let s91 = -s82;
        let s92 = 2.0 * lambda[28];
        let s93 = -s86 - s80 - s74 + s92;
        let s94 = -2.0 * lambda[28];
        let s95 = -s83;
        let s96 = 2.0 * lambda[7];
        let s97 = 2.0 * lambda[30];
        let s98 = 2.0 * lambda[32];
        let s99 = s96 - s87 + s97 + s98;
        let s100 = -2.0 * lambda[7];
        let s101 = -2.0 * lambda[30];
        let s102 = -2.0 * lambda[32];
        let s103 = -s84;
        let s104 = -s92;
        let s105 = -s96;
        let s106 = 2.0 * lambda[31];
        let s107 = -s100 - s94 - s88 + s106;
        let s108 = -2.0 * lambda[31];
        let s109 = -s97;
        let s110 = 2.0 * lambda[8];
        let s111 = s110 - s101;
        let s112 = -2.0 * lambda[8];
        let s113 = -s98;
        let s114 = -s106;
        let s115 = -s110;
        let s116 = -s112 - s108 - s102;
        values[0] = s3;
        values[1] = s4;
        values[2] = s5;
        values[3] = s6;
        values[4] = s3;
        values[5] = s4;
        values[6] = s5;
        values[7] = s6;
        values[8] = s7;
        values[9] = s9;
        values[10] = s10;
        values[11] = s7;
        values[12] = s9;
        values[13] = s10;
        values[14] = s11;
        values[15] = s15;
        values[16] = s16;
        values[17] = s17;
        values[18] = s18;
        values[19] = s11;
        values[20] = s15;
        values[21] = s16;
        values[22] = s17;
        values[23] = s18;
        values[24] = s19;
        values[25] = s20;
        values[26] = s21;
        values[27] = s23;
        values[28] = s24;
        values[29] = s19;
        values[30] = s20;
        values[31] = s21;
        values[32] = s23;
        values[33] = s24;
        values[34] = s25;
        values[35] = s29;
        values[36] = s30;
        values[37] = s31;
        values[38] = s32;
        values[39] = s25;
        values[40] = s29;
        values[41] = s30;
        values[42] = s31;
        values[43] = s32;
        values[44] = s33;
        values[45] = s34;
        values[46] = s35;
        values[47] = s37;
        values[48] = s38;
        values[49] = s33;
        values[50] = s34;
        values[51] = s35;
        values[52] = s37;
        values[53] = s38;
        values[54] = s39;
        values[55] = s43;
        values[56] = s44;
        values[57] = s45;
        values[58] = s46;
        values[59] = s39;
        values[60] = s43;
        values[61] = s44;
        values[62] = s45;
        values[63] = s46;
        values[64] = s47;
        values[65] = s48;
        values[66] = s49;
        values[67] = s51;
        values[68] = s52;
        values[69] = s47;
        values[70] = s48;
        values[71] = s49;
        values[72] = s51;
        values[73] = s52;
        values[74] = s53;
        values[75] = s57;
        values[76] = s58;
        values[77] = s59;
        values[78] = s60;
        values[79] = s53;
        values[80] = s57;
        values[81] = s58;
        values[82] = s59;
        values[83] = s60;
        values[84] = s61;
        values[85] = s62;
        values[86] = s63;
        values[87] = s65;
        values[88] = s66;
        values[89] = s61;
        values[90] = s62;
        values[91] = s63;
        values[92] = s65;
        values[93] = s66;
        values[94] = s67;
        values[95] = s71;
        values[96] = s72;
        values[97] = s73;
        values[98] = s74;
        values[99] = s67;
        values[100] = s71;
        values[101] = s72;
        values[102] = s73;
        values[103] = s74;
        values[104] = s75;
        values[105] = s76;
        values[106] = s77;
        values[107] = s79;
        values[108] = s80;
        values[109] = s75;
        values[110] = s76;
        values[111] = s77;
        values[112] = s79;
        values[113] = s80;
        values[114] = s81;
        values[115] = s85;
        values[116] = s86;
        values[117] = s87;
        values[118] = s88;
        values[119] = s81;
        values[120] = s85;
        values[121] = s86;
        values[122] = s87;
        values[123] = s88;
        values[124] = s89;
        values[125] = s90;
        values[126] = s91;
        values[127] = s93;
        values[128] = s94;
        values[129] = s89;
        values[130] = s90;
        values[131] = s91;
        values[132] = s93;
        values[133] = s94;
        values[134] = s95;
        values[135] = s99;
        values[136] = s100;
        values[137] = s101;
        values[138] = s102;
        values[139] = s95;
        values[140] = s99;
        values[141] = s100;
        values[142] = s101;
        values[143] = s102;
        values[144] = s103;
        values[145] = s104;
        values[146] = s105;
        values[147] = s107;
        values[148] = s108;
        values[149] = s103;
        values[150] = s104;
        values[151] = s105;
        values[152] = s107;
        values[153] = s108;
        values[154] = s109;
        values[155] = s111;
        values[156] = s112;
        values[157] = s109;
        values[158] = s111;
        values[159] = s112;
        values[160] = s113;
        values[161] = s114;
        values[162] = s115;
        values[163] = s116;
        values[164] = s113;
        values[165] = s114;
        values[166] = s115;
        values[167] = s116;
    }
}
