//! Builds an expression graph from arbitrary bytes, differentiates it by every variable and
//! schedules the derivatives: nothing may panic, and the scheduled straight-line code must
//! compute exactly what the graph computes.
#![no_main]

use libfuzzer_sys::fuzz_target;
use zeitner_symbolic::{Binary, Compare, Differentiator, Evaluator, Graph, Id, Program, Unary};

const VARS: u32 = 4;

/// Reads bytes as a stack program: each byte pushes a leaf or combines the top of the stack.
fn build(graph: &mut Graph, bytes: &[u8]) -> Option<Id> {
    let mut stack: Vec<Id> = Vec::new();
    let mut rest = bytes.iter().copied();
    while let Some(op) = rest.next() {
        let arg = rest.next().unwrap_or(0);
        let id = match op % 12 {
            0 => graph.var(u32::from(arg) % VARS),
            1 => graph.num(f64::from(arg as i8) / 8.0),
            2 | 3 | 4 | 5 => {
                let (b, a) = (stack.pop()?, stack.pop()?);
                match op % 12 {
                    2 => graph.add(a, b),
                    3 => graph.sub(a, b),
                    4 => graph.mul(a, b),
                    _ => graph.div(a, b),
                }
            }
            6 => {
                let a = stack.pop()?;
                graph.neg(a)
            }
            7 => {
                let a = stack.pop()?;
                graph.powi(a, i32::from(arg as i8) % 7)
            }
            8 => {
                let a = stack.pop()?;
                graph.unary(Unary::ALL[usize::from(arg) % Unary::ALL.len()], a)
            }
            9 => {
                let (b, a) = (stack.pop()?, stack.pop()?);
                graph.binary(Binary::ALL[usize::from(arg) % Binary::ALL.len()], a, b)
            }
            10 => {
                let (b, a) = (stack.pop()?, stack.pop()?);
                let p = graph.var(VARS - 1);
                let limit = graph.num(f64::from(arg as i8) / 64.0);
                let cond = graph.compare(Compare::Lt, p, limit);
                graph.select(cond, a, b)
            }
            _ => {
                let p = graph.var(VARS - 1);
                graph.call(0, vec![p])
            }
        };
        stack.push(id);
        if graph.len() > 2000 {
            return None;
        }
    }
    stack.pop()
}

fn same(a: f64, b: f64) -> bool {
    a == b || (a.is_nan() && b.is_nan())
}

fuzz_target!(|data: &[u8]| {
    let mut graph = Graph::new();
    let Some(expr) = build(&mut graph, data) else { return };
    let point = [0.3, -0.7, 1.1, 0.4];
    let call = |_: u32, a: &[f64]| a[0] * 1.5 + 0.25;
    for var in 0..VARS - 1 {
        let Ok(derivative) = Differentiator::new(var).derive(&mut graph, expr) else { continue };
        let program = Program::schedule(&graph, &[(0, expr), (1, derivative)]);
        let scheduled = program.evaluate(&|v| point[v as usize], &call);
        let mut evaluator = Evaluator::new(&graph, |v| point[v as usize], call);
        for (slot, value) in scheduled {
            let id = if slot == 0 { expr } else { derivative };
            let direct = evaluator.eval(id);
            assert!(same(value, direct), "slot {slot}: scheduled {value}, graph {direct}");
        }
    }
});
