//! Equality up to algebra ([`zeitner_symbolic::equivalent`]): expressions rewritten by the
//! rules of real arithmetic compare equal (completeness on that fragment), and expressions
//! that compare equal have equal values (soundness).

use proptest::prelude::*;
use zeitner_symbolic::{equivalent, Binary, Compare, Evaluator, Graph, Id, Unary};

const VARS: u32 = 3;

#[derive(Clone, Debug)]
enum Tree {
    Var(u32),
    Const(f64),
    Add(Box<Tree>, Box<Tree>),
    Sub(Box<Tree>, Box<Tree>),
    Mul(Box<Tree>, Box<Tree>),
    Div(Box<Tree>, Box<Tree>),
    Neg(Box<Tree>),
    Powi(Box<Tree>, i32),
    Unary(Unary, Box<Tree>),
    Binary(Binary, Box<Tree>, Box<Tree>),
    /// `if x2 < c { a } else { b }`.
    Select(f64, Box<Tree>, Box<Tree>),
}

fn tree() -> impl Strategy<Value = Tree> {
    let leaf = prop_oneof![
        (0..VARS).prop_map(Tree::Var),
        (-3.0..3.0f64).prop_map(Tree::Const),
        Just(Tree::Const(1.0)),
        Just(Tree::Const(0.1)),
    ];
    leaf.prop_recursive(5, 40, 2, |inner| {
        prop_oneof![
            (inner.clone(), inner.clone()).prop_map(|(a, b)| Tree::Add(Box::new(a), Box::new(b))),
            (inner.clone(), inner.clone()).prop_map(|(a, b)| Tree::Sub(Box::new(a), Box::new(b))),
            (inner.clone(), inner.clone()).prop_map(|(a, b)| Tree::Mul(Box::new(a), Box::new(b))),
            (inner.clone(), inner.clone()).prop_map(|(a, b)| Tree::Div(Box::new(a), Box::new(b))),
            inner.clone().prop_map(|a| Tree::Neg(Box::new(a))),
            (inner.clone(), -2..4i32).prop_map(|(a, n)| Tree::Powi(Box::new(a), n)),
            (
                proptest::sample::select(vec![Unary::Sin, Unary::Exp, Unary::Abs, Unary::Atan]),
                inner.clone()
            )
                .prop_map(|(f, a)| Tree::Unary(f, Box::new(a))),
            (
                proptest::sample::select(Binary::ALL.to_vec()),
                inner.clone(),
                inner.clone()
            )
                .prop_map(|(f, a, b)| Tree::Binary(f, Box::new(a), Box::new(b))),
            (-1.0..1.0f64, inner.clone(), inner).prop_map(|(c, a, b)| Tree::Select(
                c,
                Box::new(a),
                Box::new(b)
            )),
        ]
    })
}

fn build(g: &mut Graph, tree: &Tree) -> Id {
    match tree {
        Tree::Var(v) => g.var(*v),
        Tree::Const(c) => g.num(*c),
        Tree::Add(a, b) => {
            let (a, b) = (build(g, a), build(g, b));
            g.add(a, b)
        }
        Tree::Sub(a, b) => {
            let (a, b) = (build(g, a), build(g, b));
            g.sub(a, b)
        }
        Tree::Mul(a, b) => {
            let (a, b) = (build(g, a), build(g, b));
            g.mul(a, b)
        }
        Tree::Div(a, b) => {
            let (a, b) = (build(g, a), build(g, b));
            g.div(a, b)
        }
        Tree::Neg(a) => {
            let a = build(g, a);
            g.neg(a)
        }
        Tree::Powi(a, n) => {
            let a = build(g, a);
            g.powi(a, *n)
        }
        Tree::Unary(f, a) => {
            let a = build(g, a);
            g.unary(*f, a)
        }
        Tree::Binary(f, a, b) => {
            let (a, b) = (build(g, a), build(g, b));
            g.binary(*f, a, b)
        }
        Tree::Select(c, a, b) => {
            let (a, b) = (build(g, a), build(g, b));
            let x = g.var(VARS - 1);
            let limit = g.num(*c);
            let cond = g.compare(Compare::Lt, x, limit);
            g.select(cond, a, b)
        }
    }
}

/// The same expression, rewritten by the rules of real arithmetic as chosen by `choices`:
/// operands of `+`, `*`, `hypot`, `min`, `max` swapped, `a - b` as `a + (-1)·b`, `a / b` as
/// `a · b^-1`, sums and products reassociated, `-a` as `(-1)·a`.
fn rewrite(tree: &Tree, choices: &mut impl Iterator<Item = u8>) -> Tree {
    let boxed = |t: Tree| Box::new(t);
    match tree {
        Tree::Var(_) | Tree::Const(_) => tree.clone(),
        Tree::Add(a, b) => {
            let (a, b) = (rewrite(a, choices), rewrite(b, choices));
            match (choices.next().unwrap_or(0) % 3, &b) {
                (0, _) => Tree::Add(boxed(b), boxed(a)),
                // a + (c + d) = (a + c) + d
                (1, Tree::Add(c, d)) => Tree::Add(boxed(Tree::Add(boxed(a), c.clone())), d.clone()),
                _ => Tree::Add(boxed(a), boxed(b)),
            }
        }
        Tree::Sub(a, b) => {
            let (a, b) = (rewrite(a, choices), rewrite(b, choices));
            match choices.next().unwrap_or(0) % 2 {
                0 => Tree::Add(
                    boxed(a),
                    boxed(Tree::Mul(boxed(Tree::Const(-1.0)), boxed(b))),
                ),
                _ => Tree::Neg(boxed(Tree::Sub(boxed(b), boxed(a)))),
            }
        }
        Tree::Mul(a, b) => {
            let (a, b) = (rewrite(a, choices), rewrite(b, choices));
            match (choices.next().unwrap_or(0) % 3, &b) {
                (0, _) => Tree::Mul(boxed(b), boxed(a)),
                (1, Tree::Mul(c, d)) => Tree::Mul(boxed(Tree::Mul(boxed(a), c.clone())), d.clone()),
                _ => Tree::Mul(boxed(a), boxed(b)),
            }
        }
        Tree::Div(a, b) => {
            let (a, b) = (rewrite(a, choices), rewrite(b, choices));
            match choices.next().unwrap_or(0) % 2 {
                0 => Tree::Mul(boxed(a), boxed(Tree::Powi(boxed(b), -1))),
                _ => Tree::Div(boxed(a), boxed(b)),
            }
        }
        Tree::Neg(a) => {
            let a = rewrite(a, choices);
            match choices.next().unwrap_or(0) % 2 {
                0 => Tree::Mul(boxed(Tree::Const(-1.0)), boxed(a)),
                _ => Tree::Neg(boxed(a)),
            }
        }
        Tree::Powi(a, n) => Tree::Powi(boxed(rewrite(a, choices)), *n),
        Tree::Unary(f, a) => Tree::Unary(*f, boxed(rewrite(a, choices))),
        Tree::Binary(f, a, b) => {
            let (a, b) = (rewrite(a, choices), rewrite(b, choices));
            let symmetric = matches!(f, Binary::Hypot | Binary::Min | Binary::Max);
            if symmetric && choices.next().unwrap_or(0).is_multiple_of(2) {
                Tree::Binary(*f, boxed(b), boxed(a))
            } else {
                Tree::Binary(*f, boxed(a), boxed(b))
            }
        }
        Tree::Select(c, a, b) => {
            Tree::Select(*c, boxed(rewrite(a, choices)), boxed(rewrite(b, choices)))
        }
    }
}

/// `tree` with its first constant changed, or a variable replaced: usually a different value.
fn mutate(tree: &Tree, done: &mut bool) -> Tree {
    let boxed = |t: Tree| Box::new(t);
    if *done {
        return tree.clone();
    }
    match tree {
        Tree::Const(c) => {
            *done = true;
            Tree::Const(c * 1.001 + 1e-3)
        }
        Tree::Var(v) => {
            *done = true;
            Tree::Var((v + 1) % VARS)
        }
        Tree::Add(a, b) => Tree::Add(boxed(mutate(a, done)), boxed(mutate(b, done))),
        Tree::Sub(a, b) => Tree::Sub(boxed(mutate(a, done)), boxed(mutate(b, done))),
        Tree::Mul(a, b) => Tree::Mul(boxed(mutate(a, done)), boxed(mutate(b, done))),
        Tree::Div(a, b) => Tree::Div(boxed(mutate(a, done)), boxed(mutate(b, done))),
        Tree::Neg(a) => Tree::Neg(boxed(mutate(a, done))),
        Tree::Powi(a, n) => Tree::Powi(boxed(mutate(a, done)), *n),
        Tree::Unary(f, a) => Tree::Unary(*f, boxed(mutate(a, done))),
        Tree::Binary(f, a, b) => Tree::Binary(*f, boxed(mutate(a, done)), boxed(mutate(b, done))),
        Tree::Select(c, a, b) => Tree::Select(*c, boxed(mutate(a, done)), boxed(mutate(b, done))),
    }
}

fn value(g: &Graph, id: Id, point: &[f64; 3]) -> f64 {
    Evaluator::new(g, |v| point[v as usize], |_, _: &[f64]| 0.0).eval(id)
}

proptest! {
    #![proptest_config(ProptestConfig {
        cases: 2000,
        rng_seed: proptest::test_runner::RngSeed::Fixed(0x5e3d),
        ..ProptestConfig::default()
    })]

    /// Whatever the rewrite, the two forms are recognised as one expression.
    #[test]
    fn rewritten_expressions_are_equivalent(
        tree in tree(),
        choices in proptest::collection::vec(any::<u8>(), 64),
    ) {
        let mut g = Graph::new();
        let a = build(&mut g, &tree);
        let rewritten = rewrite(&tree, &mut choices.into_iter());
        let b = build(&mut g, &rewritten);
        // NaN and infinite constants (`(-1.5).powf(0.5)`) are equal to nothing, not even
        // themselves; a model may not hold them.
        prop_assume!((0..g.len()).all(|i| g.constant(Id(i as u32)).is_none_or(f64::is_finite)));
        prop_assert!(equivalent(&g, a, b), "{tree:?}\nrewritten {rewritten:?}");
        // The order of the comparison does not matter.
        prop_assert!(equivalent(&g, b, a));
    }

    /// Expressions called equivalent have equal values (where they are finite).
    #[test]
    fn equivalent_expressions_have_equal_values(
        tree in tree(),
        other in tree(),
        mutate_it in any::<bool>(),
        points in proptest::collection::vec(proptest::array::uniform3(-2.0..2.0f64), 5),
    ) {
        let mut g = Graph::new();
        let a = build(&mut g, &tree);
        let second = if mutate_it { mutate(&tree, &mut false) } else { other };
        let b = build(&mut g, &second);
        if equivalent(&g, a, b) {
            for point in &points {
                let (x, y) = (value(&g, a, point), value(&g, b, point));
                if x.is_finite() && y.is_finite() && x.abs() < 1e6 {
                    prop_assert!(
                        (x - y).abs() <= 1e-9 * x.abs().max(1.0),
                        "called equivalent but {x} != {y} at {point:?}: {tree:?} vs {second:?}"
                    );
                }
            }
        }
    }
}

fn vars(g: &mut Graph) -> (Id, Id) {
    (g.var(0), g.var(1))
}

#[test]
fn the_reported_symmetric_entries_are_equivalent() {
    let mut g = Graph::new();
    let (x, y) = vars(&mut g);
    let (tenth, one) = (g.num(0.1), g.num(1.0));
    // 0.1*(x+(y+1.0)) and 0.1*((x+y)+1.0)
    let y1 = g.add(y, one);
    let inner = g.add(x, y1);
    let left = g.mul(tenth, inner);
    let xy = g.add(x, y);
    let inner = g.add(xy, one);
    let right = g.mul(tenth, inner);
    assert_ne!(left, right);
    assert!(equivalent(&g, left, right));
    // 0.1*x*y and y*x*0.1
    let tx = g.mul(tenth, x);
    let left = g.mul(tx, y);
    let yx = g.mul(y, x);
    let right = g.mul(yx, tenth);
    assert_ne!(left, right);
    assert!(equivalent(&g, left, right));
}

#[test]
fn algebra_beyond_reordering() {
    let mut g = Graph::new();
    let (x, y) = vars(&mut g);
    let two = g.num(2.0);
    // (x + y)² = x² + 2xy + y²
    let sum = g.add(x, y);
    let square = g.powi(sum, 2);
    let x2 = g.powi(x, 2);
    let y2 = g.powi(y, 2);
    let xy = g.mul(x, y);
    let two_xy = g.mul(two, xy);
    let partial = g.add(x2, two_xy);
    let expanded = g.add(partial, y2);
    assert!(equivalent(&g, square, expanded));
    // x / 2 = 0.5 x, 0.1·3·x = 0.3·x (coefficients agree within their rounding)
    let half = g.div(x, two);
    let point_five = g.num(0.5);
    let half_x = g.mul(point_five, x);
    assert!(equivalent(&g, half, half_x));
    let (tenth, three, point_three) = (g.num(0.1), g.num(3.0), g.num(0.3));
    let tenth_x = g.mul(tenth, x);
    let thrice = g.mul(three, tenth_x);
    let direct = g.mul(point_three, x);
    assert!(equivalent(&g, thrice, direct));
    // sin(x + y) = sin(y + x) inside functions, min(x, y) = min(y, x)
    let sin_xy = g.unary(Unary::Sin, sum);
    let yx = g.add(y, x);
    let sin_yx = g.unary(Unary::Sin, yx);
    assert!(equivalent(&g, sin_xy, sin_yx));
    let min_xy = g.binary(Binary::Min, x, y);
    let min_yx = g.binary(Binary::Min, y, x);
    assert!(equivalent(&g, min_xy, min_yx));
}

#[test]
fn different_expressions_are_not_equivalent() {
    let mut g = Graph::new();
    let (x, y) = vars(&mut g);
    assert!(!equivalent(&g, x, y));
    let abs = g.unary(Unary::Abs, x);
    assert!(!equivalent(&g, abs, x));
    let tiny = g.num(1e-9);
    let shifted = g.add(x, tiny);
    assert!(!equivalent(&g, shifted, x));
    // (x + 1)² ≠ x² + 1
    let one = g.one();
    let x1 = g.add(x, one);
    let square = g.powi(x1, 2);
    let x2 = g.powi(x, 2);
    let wrong = g.add(x2, one);
    assert!(!equivalent(&g, square, wrong));
    // atan2 is not symmetric
    let a = g.binary(Binary::Atan2, x, y);
    let b = g.binary(Binary::Atan2, y, x);
    assert!(!equivalent(&g, a, b));
}

#[test]
fn long_and_deep_expressions_need_no_deep_stack() {
    let run = || {
        let mut g = Graph::new();
        let x = g.var(0);
        let y = g.var(1);
        // A 20 000-term sum in two orders, and a product nested 20 000 deep.
        let mut forward = g.zero();
        let mut backward = g.zero();
        let terms: Vec<Id> = (0..20_000)
            .map(|i| {
                let c = g.num(f64::from(i) + 1.0);
                let v = g.var(2 + i % 50);
                g.mul(c, v)
            })
            .collect();
        for &t in &terms {
            forward = g.add(forward, t);
        }
        for &t in terms.iter().rev() {
            backward = g.add(t, backward);
        }
        assert!(equivalent(&g, forward, backward));
        let mut deep = x;
        for _ in 0..20_000 {
            deep = g.mul(y, deep);
            deep = g.unary(Unary::Sin, deep);
        }
        assert!(equivalent(&g, deep, deep));
        let other = g.add(deep, x);
        assert!(!equivalent(&g, deep, other));
    };
    std::thread::Builder::new()
        .stack_size(256 * 1024)
        .spawn(run)
        .unwrap()
        .join()
        .unwrap();
}
