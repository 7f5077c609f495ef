//! Equality up to algebra, for checks such as the symmetry of a mass matrix: two expressions
//! written differently (`0.1*(x+(y+1.0))` and `0.1*((x+y)+1.0)`, `0.1*x*y` and `y*x*0.1`) are
//! the same entry.
//!
//! Each expression is brought into a canonical form: a sum of terms `c · a₁^k₁ · … · aₘ^kₘ`,
//! where the atoms `aᵢ` are variables or functions (`sin`, `atan2`, `if`, opaque calls) of
//! canonical arguments, sums and products are flattened and sorted, constants are combined,
//! products and integer powers of sums are expanded while the result stays small
//! ([`MAX_TERMS`]), and a quotient by a sum is a power `-1` of that sum as an atom. Two
//! canonical forms are equal when they have the same terms and coefficients that agree within
//! the rounding of their computation (each coefficient carries the sum of the magnitudes it was
//! computed from). The rules are those of the real numbers, so the check is exact algebra, not
//! sampling: it never calls two different expressions equal because they agree at a few
//! points, which piecewise functions (`abs`, `min`, `if`) would make unsafe. What it does not
//! know (trigonometric identities, `sqrt(x²) = |x|`) it reports as different.
//!
//! Every pass is iterative, in the graph's topological order, so deep expressions need no
//! deep stack.

use std::collections::{BTreeMap, HashMap};

use crate::graph::{Binary, Compare, Cond, CondId, Graph, Id, Node, Unary};

/// Products and powers of sums are expanded only while they have at most this many terms;
/// larger ones stay atoms.
pub const MAX_TERMS: usize = 256;

/// Work (terms created) after which the comparison gives up and reports "different".
const BUDGET: usize = 2_000_000;

/// Significant digits of the coefficients in the arguments of functions (see [`Poly::key`]).
const KEY_DIGITS: usize = 12;

/// Relative agreement of two coefficients, in units of the magnitude they were computed from.
const TOLERANCE: f64 = 1e-12;

/// An atom: identified by its index in [`Canonicalizer::atoms`].
type Atom = u32;
/// `a₁^k₁ · … · aₘ^kₘ`, sorted by atom, no zero exponents.
type Monomial = Vec<(Atom, i32)>;

/// A coefficient and the sum of the magnitudes of what it was computed from, which bounds its
/// rounding error.
#[derive(Clone, Copy, Debug)]
struct Coefficient {
    value: f64,
    magnitude: f64,
}

impl Coefficient {
    fn new(value: f64) -> Self {
        Coefficient {
            value,
            magnitude: value.abs(),
        }
    }

    fn add(self, other: Coefficient) -> Coefficient {
        Coefficient {
            value: self.value + other.value,
            magnitude: self.magnitude + other.magnitude,
        }
    }

    fn mul(self, other: Coefficient) -> Coefficient {
        Coefficient {
            value: self.value * other.value,
            magnitude: self.magnitude * other.magnitude,
        }
    }

    fn neg(self) -> Coefficient {
        Coefficient {
            value: -self.value,
            magnitude: self.magnitude,
        }
    }

    /// Zero up to rounding: the result of cancellation.
    fn vanishes(self) -> bool {
        self.value.abs() <= TOLERANCE * self.magnitude
    }
}

/// A canonical sum of terms.
#[derive(Clone, Debug, Default)]
struct Poly {
    terms: BTreeMap<Monomial, Coefficient>,
}

impl Poly {
    fn constant(value: f64) -> Poly {
        let mut terms = BTreeMap::new();
        if value != 0.0 {
            terms.insert(Vec::new(), Coefficient::new(value));
        }
        Poly { terms }
    }

    fn atom(atom: Atom, exponent: i32) -> Poly {
        let mut terms = BTreeMap::new();
        terms.insert(vec![(atom, exponent)], Coefficient::new(1.0));
        Poly { terms }
    }

    fn add_term(&mut self, monomial: Monomial, coefficient: Coefficient) {
        match self.terms.get_mut(&monomial) {
            Some(existing) => {
                *existing = existing.add(coefficient);
                // Exact zeros go; near zeros stay, so the comparison can judge them.
                if existing.value == 0.0 {
                    self.terms.remove(&monomial);
                }
            }
            None => {
                if coefficient.value != 0.0 {
                    self.terms.insert(monomial, coefficient);
                }
            }
        }
    }

    fn negate(mut self) -> Poly {
        for coefficient in self.terms.values_mut() {
            *coefficient = coefficient.neg();
        }
        self
    }

    /// The identity of the form, for keying atoms on their arguments: coefficients rounded to
    /// [`KEY_DIGITS`] significant digits, so that `sin(x / 0.1)` and `sin(x · 0.1⁻¹)` (whose
    /// folded constants differ in the last bit) are one atom; terms that vanish by
    /// cancellation left out.
    fn key(&self) -> Vec<(Monomial, String)> {
        self.terms
            .iter()
            .filter(|(_, c)| !c.vanishes())
            .map(|(m, c)| (m.clone(), format!("{:.*e}", KEY_DIGITS - 1, c.value)))
            .collect()
    }

    fn single_term(&self) -> Option<(&Monomial, Coefficient)> {
        match self.terms.len() {
            1 => self.terms.iter().next().map(|(m, c)| (m, *c)),
            _ => None,
        }
    }
}

/// What an atom is, with canonical arguments (indices into the form table).
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
enum AtomKey {
    Var(u32),
    /// A sum kept whole (divided by, raised to a power, or too large to expand).
    Sum(usize),
    Unary(Unary, usize),
    Binary(Binary, usize, usize),
    Select(usize, usize, usize),
    Call(u32, Vec<usize>),
}

/// Conditions, canonical up to the order of `&&`, `||` operands.
#[derive(Clone, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
enum CondKey {
    Compare(u8, usize, usize),
    And(usize, usize),
    Or(usize, usize),
    Not(usize),
}

struct Canonicalizer<'g> {
    graph: &'g Graph,
    atoms: HashMap<AtomKey, Atom>,
    /// Exact keys of the forms used as arguments, interned.
    forms: HashMap<Vec<(Monomial, String)>, usize>,
    conds: HashMap<CondKey, usize>,
    /// The sums kept whole, by their atom.
    sums: HashMap<Atom, Poly>,
    work: usize,
}

/// Whether `a` and `b` are the same expression by the rules of real arithmetic (see the module
/// documentation). `false` when they differ or when deciding would take too long.
pub fn equivalent(graph: &Graph, a: Id, b: Id) -> bool {
    if a == b {
        return true;
    }
    let mut canonicalizer = Canonicalizer {
        graph,
        atoms: HashMap::new(),
        forms: HashMap::new(),
        conds: HashMap::new(),
        sums: HashMap::new(),
        work: 0,
    };
    let Some(mut forms) = canonicalizer.forms_of(&[a, b]) else {
        return false;
    };
    let (Some(q), Some(p)) = (forms.pop(), forms.pop()) else {
        return false;
    };
    same(&p, &q)
}

/// Equal terms, coefficients equal up to the rounding of their computation.
fn same(p: &Poly, q: &Poly) -> bool {
    let zero = Coefficient {
        value: 0.0,
        magnitude: 0.0,
    };
    let monomials: std::collections::BTreeSet<&Monomial> =
        p.terms.keys().chain(q.terms.keys()).collect();
    monomials.into_iter().all(|m| {
        let x = p.terms.get(m).copied().unwrap_or(zero);
        let y = q.terms.get(m).copied().unwrap_or(zero);
        (x.value - y.value).abs() <= TOLERANCE * x.magnitude.max(y.magnitude)
    })
}

impl Canonicalizer<'_> {
    /// The canonical forms of `roots`, computed bottom-up in id order (children have smaller
    /// ids), each node's form dropped once its last parent has used it.
    fn forms_of(&mut self, roots: &[Id]) -> Option<Vec<Poly>> {
        let graph = self.graph;
        // Reachable nodes and conditions, and how often each node is used.
        let mut uses: HashMap<Id, usize> = HashMap::new();
        let mut reachable_conds: Vec<CondId> = Vec::new();
        let mut seen_conds: HashMap<CondId, ()> = HashMap::new();
        let mut stack: Vec<Id> = roots.to_vec();
        for &root in roots {
            *uses.entry(root).or_default() += 1;
        }
        let mut visited: HashMap<Id, ()> = HashMap::new();
        while let Some(id) = stack.pop() {
            if visited.insert(id, ()).is_some() {
                continue;
            }
            let mut operands = Vec::new();
            match graph.node(id) {
                Node::Const(_) | Node::Var(_) => {}
                Node::Add(a, b)
                | Node::Sub(a, b)
                | Node::Mul(a, b)
                | Node::Div(a, b)
                | Node::Binary(_, a, b) => operands.extend([*a, *b]),
                Node::Neg(a) | Node::Powi(a, _) | Node::Unary(_, a) => operands.push(*a),
                Node::Select(c, a, b) => {
                    operands.extend([*a, *b]);
                    let mut cond_stack = vec![*c];
                    while let Some(c) = cond_stack.pop() {
                        if seen_conds.insert(c, ()).is_some() {
                            continue;
                        }
                        reachable_conds.push(c);
                        match graph.cond(c) {
                            Cond::Compare(_, x, y) => operands.extend([*x, *y]),
                            Cond::And(x, y) | Cond::Or(x, y) => cond_stack.extend([*x, *y]),
                            Cond::Not(x) => cond_stack.push(*x),
                        }
                    }
                }
                Node::Call(_, args) => operands.extend(args.iter().copied()),
            }
            for operand in operands {
                *uses.entry(operand).or_default() += 1;
                stack.push(operand);
            }
        }
        let mut order: Vec<Id> = visited.into_keys().collect();
        order.sort();
        reachable_conds.sort();
        let mut forms: HashMap<Id, Poly> = HashMap::new();
        let mut cond_keys: HashMap<CondId, usize> = HashMap::new();
        // Conditions refer to nodes of smaller ids than the selects that use them, but not
        // necessarily smaller than other nodes: each is keyed when its select is reached.
        for id in order {
            let form = self.form(id, &mut forms, &mut uses, &mut cond_keys)?;
            forms.insert(id, form);
            if self.work > BUDGET {
                return None;
            }
        }
        roots.iter().map(|root| forms.get(root).cloned()).collect()
    }

    /// The form of an operand, taken when this is its last use.
    fn operand(
        &self,
        id: Id,
        forms: &mut HashMap<Id, Poly>,
        uses: &mut HashMap<Id, usize>,
    ) -> Poly {
        let count = uses.get_mut(&id).map(|c| {
            *c = c.saturating_sub(1);
            *c
        });
        if count == Some(0) {
            forms.remove(&id).unwrap_or_default()
        } else {
            forms.get(&id).cloned().unwrap_or_default()
        }
    }

    /// The argument index of an operand's form (for atoms).
    fn argument(
        &mut self,
        id: Id,
        forms: &mut HashMap<Id, Poly>,
        uses: &mut HashMap<Id, usize>,
    ) -> usize {
        let form = self.operand(id, forms, uses);
        self.intern_form(&form)
    }

    fn intern_form(&mut self, form: &Poly) -> usize {
        let key = form.key();
        let next = self.forms.len();
        *self.forms.entry(key).or_insert(next)
    }

    fn atom(&mut self, key: AtomKey) -> Atom {
        let next = self.atoms.len() as Atom;
        *self.atoms.entry(key).or_insert(next)
    }

    fn form(
        &mut self,
        id: Id,
        forms: &mut HashMap<Id, Poly>,
        uses: &mut HashMap<Id, usize>,
        cond_keys: &mut HashMap<CondId, usize>,
    ) -> Option<Poly> {
        let graph = self.graph;
        Some(match graph.node(id).clone() {
            Node::Const(bits) => Poly::constant(f64::from_bits(bits)),
            Node::Var(v) => Poly::atom(self.atom(AtomKey::Var(v)), 1),
            Node::Add(a, b) | Node::Sub(a, b) => {
                let subtract = matches!(graph.node(id), Node::Sub(..));
                let (x, y) = (self.operand(a, forms, uses), self.operand(b, forms, uses));
                let y = if subtract { y.negate() } else { y };
                // Merge the smaller into the larger: a long sum costs one insertion per term.
                if x.terms.len() >= y.terms.len() {
                    self.merged(x, y)
                } else {
                    self.merged(y, x)
                }
            }
            Node::Neg(a) => self.operand(a, forms, uses).negate(),
            Node::Mul(a, b) => {
                let (x, y) = (self.operand(a, forms, uses), self.operand(b, forms, uses));
                self.product(x, y)
            }
            Node::Div(a, b) => {
                let (x, y) = (self.operand(a, forms, uses), self.operand(b, forms, uses));
                let inverse = self.power(y, -1);
                self.product(x, inverse)
            }
            Node::Powi(a, n) => {
                let x = self.operand(a, forms, uses);
                self.power(x, n)
            }
            Node::Unary(f, a) => {
                let x = self.argument(a, forms, uses);
                Poly::atom(self.atom(AtomKey::Unary(f, x)), 1)
            }
            Node::Binary(f, a, b) => {
                let (x, y) = (self.argument(a, forms, uses), self.argument(b, forms, uses));
                // hypot, min and max do not depend on the order of their arguments.
                let (x, y) = match f {
                    Binary::Hypot | Binary::Min | Binary::Max if y < x => (y, x),
                    _ => (x, y),
                };
                Poly::atom(self.atom(AtomKey::Binary(f, x, y)), 1)
            }
            Node::Select(c, a, b) => {
                let cond = self.cond_key(c, forms, uses, cond_keys);
                let (x, y) = (self.argument(a, forms, uses), self.argument(b, forms, uses));
                Poly::atom(self.atom(AtomKey::Select(cond, x, y)), 1)
            }
            Node::Call(f, args) => {
                let args = args
                    .iter()
                    .map(|&arg| self.argument(arg, forms, uses))
                    .collect();
                Poly::atom(self.atom(AtomKey::Call(f, args)), 1)
            }
        })
    }

    /// The key of a condition, iteratively: conditions of smaller ids first.
    fn cond_key(
        &mut self,
        cond: CondId,
        forms: &mut HashMap<Id, Poly>,
        uses: &mut HashMap<Id, usize>,
        cond_keys: &mut HashMap<CondId, usize>,
    ) -> usize {
        let graph = self.graph;
        let mut pending = vec![cond];
        let mut order = Vec::new();
        while let Some(c) = pending.pop() {
            if cond_keys.contains_key(&c) || order.contains(&c) {
                continue;
            }
            order.push(c);
            match graph.cond(c) {
                Cond::Compare(..) => {}
                Cond::And(x, y) | Cond::Or(x, y) => pending.extend([*x, *y]),
                Cond::Not(x) => pending.push(*x),
            }
        }
        order.sort();
        for c in order {
            let key = match graph.cond(c).clone() {
                Cond::Compare(op, a, b) => {
                    let (x, y) = (self.argument(a, forms, uses), self.argument(b, forms, uses));
                    CondKey::Compare(compare_code(op), x, y)
                }
                Cond::And(a, b) | Cond::Or(a, b) => {
                    let (x, y) = (cond_keys[&a], cond_keys[&b]);
                    let (x, y) = if y < x { (y, x) } else { (x, y) };
                    if matches!(graph.cond(c), Cond::And(..)) {
                        CondKey::And(x, y)
                    } else {
                        CondKey::Or(x, y)
                    }
                }
                Cond::Not(a) => CondKey::Not(cond_keys[&a]),
            };
            let next = self.conds.len();
            let index = *self.conds.entry(key).or_insert(next);
            cond_keys.insert(c, index);
        }
        cond_keys[&cond]
    }

    fn merged(&mut self, mut into: Poly, from: Poly) -> Poly {
        self.work += from.terms.len();
        for (monomial, coefficient) in from.terms {
            into.add_term(monomial, coefficient);
        }
        into
    }

    /// `x · y`, distributed when one factor is a single term or the result has at most
    /// [`MAX_TERMS`] terms; otherwise both sums are kept whole.
    fn product(&mut self, x: Poly, y: Poly) -> Poly {
        let small = x.terms.len() <= 1
            || y.terms.len() <= 1
            || x.terms.len().saturating_mul(y.terms.len()) <= MAX_TERMS;
        let (x, y) = if small {
            (x, y)
        } else {
            (self.whole(x, 1), self.whole(y, 1))
        };
        self.work += x.terms.len() * y.terms.len();
        let mut out = Poly::default();
        for (mx, cx) in &x.terms {
            for (my, cy) in &y.terms {
                out.add_term(multiply(mx, my), cx.mul(*cy));
            }
        }
        out
    }

    /// `x^n`: a single term raises its parts; a sum is expanded while small, otherwise kept
    /// whole as an atom raised to `n`.
    fn power(&mut self, x: Poly, n: i32) -> Poly {
        match n {
            0 => return Poly::constant(1.0),
            1 => return x,
            _ => {}
        }
        if x.terms.is_empty() {
            // 0^n: zero for positive n, a division by zero otherwise; keep it visible.
            return if n > 0 { x } else { self.whole(x, n) };
        }
        if let Some((monomial, coefficient)) = x.single_term() {
            let raised: Option<Monomial> = monomial
                .iter()
                .map(|&(atom, k)| k.checked_mul(n).map(|k| (atom, k)))
                .collect();
            if let Some(raised) = raised {
                let value = coefficient.value.powi(n);
                let mut out = Poly::default();
                out.add_term(
                    Vec::new(),
                    Coefficient {
                        value,
                        magnitude: value.abs(),
                    },
                );
                let mut kept = Vec::new();
                for (atom, k) in raised {
                    // A sum kept whole by `(s)⁻¹` and raised back to a positive power is expanded
                    // again, as if written out: `1 / (1 / (x + y))` is `x + y`.
                    match self.sums.get(&atom) {
                        Some(sum) if k > 0 => {
                            let sum = sum.clone();
                            let factor = self.power(sum, k);
                            out = self.product(out, factor);
                        }
                        _ => kept.push((atom, k)),
                    }
                }
                let mut rest = Poly::default();
                rest.add_term(kept, Coefficient::new(1.0));
                return self.product(out, rest);
            }
        }
        let terms = x.terms.len();
        let expandable = n > 1
            && u32::try_from(n)
                .ok()
                .and_then(|n| terms.checked_pow(n))
                .is_some_and(|size| size <= MAX_TERMS);
        if expandable {
            let mut out = x.clone();
            for _ in 1..n {
                out = self.product(out, x.clone());
            }
            return out;
        }
        self.whole(x, n)
    }

    /// `x` as one atom raised to `n`.
    fn whole(&mut self, x: Poly, n: i32) -> Poly {
        let form = self.intern_form(&x);
        let atom = self.atom(AtomKey::Sum(form));
        self.sums.entry(atom).or_insert(x);
        Poly::atom(atom, n)
    }
}

fn multiply(x: &Monomial, y: &Monomial) -> Monomial {
    let mut out: Monomial = Vec::with_capacity(x.len() + y.len());
    let (mut i, mut j) = (0, 0);
    while i < x.len() || j < y.len() {
        let next = match (x.get(i), y.get(j)) {
            (Some(&(a, k)), Some(&(b, l))) if a == b => {
                i += 1;
                j += 1;
                // An exponent overflow keeps both factors apart rather than wrapping.
                match k.checked_add(l) {
                    Some(sum) => (a, sum),
                    None => {
                        out.push((a, k));
                        (b, l)
                    }
                }
            }
            (Some(&(a, k)), Some(&(b, _))) if a < b => {
                i += 1;
                (a, k)
            }
            (Some(_), Some(&(b, l))) => {
                j += 1;
                (b, l)
            }
            (Some(&(a, k)), None) => {
                i += 1;
                (a, k)
            }
            (None, Some(&(b, l))) => {
                j += 1;
                (b, l)
            }
            (None, None) => break,
        };
        if next.1 != 0 {
            out.push(next);
        }
    }
    out
}

fn compare_code(op: Compare) -> u8 {
    match op {
        Compare::Lt => 0,
        Compare::Le => 1,
        Compare::Gt => 2,
        Compare::Ge => 3,
        Compare::Eq => 4,
        Compare::Ne => 5,
    }
}
