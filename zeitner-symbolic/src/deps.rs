//! Which variables each expression depends on, computed once per node, bottom-up and
//! iteratively, and kept: asking about every row of a model costs the size of the graph, not
//! the size of the graph per row.

use std::rc::Rc;

use crate::graph::{Graph, Id};
use crate::program::children;

/// The sorted variables of every node asked about so far (and of their operands). Nodes never
/// change once built, so the table stays valid while the graph grows.
#[derive(Default)]
pub struct Dependencies {
    sets: Vec<Option<Rc<[u32]>>>,
}

impl Dependencies {
    pub fn new() -> Self {
        Self::default()
    }

    /// The variables `id` depends on, sorted, through any path (conditions and the arguments of
    /// opaque calls included).
    pub fn of(&mut self, graph: &Graph, id: Id) -> Rc<[u32]> {
        if self.sets.len() < graph.len() {
            self.sets.resize(graph.len(), None);
        }
        let mut stack = vec![id];
        while let Some(&top) = stack.last() {
            if self.sets[top.0 as usize].is_some() {
                stack.pop();
                continue;
            }
            let operands = children(graph, top);
            let before = stack.len();
            for &operand in &operands {
                if self.sets[operand.0 as usize].is_none() {
                    stack.push(operand);
                }
            }
            if stack.len() != before {
                continue;
            }
            let set: Rc<[u32]> = match (graph.node(top), operands.as_slice()) {
                (crate::graph::Node::Var(v), _) => Rc::from(vec![*v]),
                (_, []) => Rc::from(Vec::new()),
                (_, [a]) => self.known(*a),
                (_, [a, b]) => merge(&self.known(*a), &self.known(*b)),
                (_, many) => {
                    let mut all: Vec<u32> = many
                        .iter()
                        .flat_map(|&o| self.known(o).iter().copied().collect::<Vec<_>>())
                        .collect();
                    all.sort_unstable();
                    all.dedup();
                    Rc::from(all)
                }
            };
            self.sets[top.0 as usize] = Some(set);
            stack.pop();
        }
        self.known(id)
    }

    fn known(&self, id: Id) -> Rc<[u32]> {
        self.sets[id.0 as usize]
            .clone()
            .expect("operands are computed first")
    }

    /// Whether `id` depends on any variable for which `is_var` holds.
    pub fn any(&mut self, graph: &Graph, id: Id, is_var: impl Fn(u32) -> bool) -> bool {
        self.of(graph, id).iter().any(|&v| is_var(v))
    }
}

/// The union of two sorted sets; shares one of them when it holds the other.
fn merge(a: &Rc<[u32]>, b: &Rc<[u32]>) -> Rc<[u32]> {
    if b.is_empty() || Rc::ptr_eq(a, b) {
        return a.clone();
    }
    if a.is_empty() {
        return b.clone();
    }
    let mut out = Vec::with_capacity(a.len() + b.len());
    let (mut i, mut j) = (0, 0);
    while i < a.len() && j < b.len() {
        match a[i].cmp(&b[j]) {
            std::cmp::Ordering::Less => {
                out.push(a[i]);
                i += 1;
            }
            std::cmp::Ordering::Greater => {
                out.push(b[j]);
                j += 1;
            }
            std::cmp::Ordering::Equal => {
                out.push(a[i]);
                i += 1;
                j += 1;
            }
        }
    }
    out.extend_from_slice(&a[i..]);
    out.extend_from_slice(&b[j..]);
    if out.len() == a.len() {
        return a.clone();
    }
    if out.len() == b.len() {
        return b.clone();
    }
    Rc::from(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn variables_of_shared_and_deep_expressions() {
        let mut g = Graph::new();
        let (x, y, z) = (g.var(0), g.var(1), g.var(2));
        let xy = g.mul(x, y);
        let s = g.add(xy, z);
        let mut deps = Dependencies::new();
        assert_eq!(&*deps.of(&g, s), &[0, 1, 2]);
        assert_eq!(&*deps.of(&g, xy), &[0, 1]);
        let c = g.num(2.0);
        assert!(deps.of(&g, c).is_empty());
        // A long chain is walked without recursion.
        let mut sum = x;
        for k in 0..100_000 {
            let v = g.var(3 + (k % 7));
            let t = g.mul(v, sum);
            sum = g.add(t, y);
        }
        assert_eq!(deps.of(&g, sum).len(), 9);
        assert!(deps.any(&g, sum, |v| v == 5));
    }
}
