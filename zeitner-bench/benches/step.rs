//! One accepted step, per scene and method: the micro-benchmark beneath the work-precision
//! report, for changes to the step itself
//! (`cargo bench -p zeitner-bench --features criterion --bench step`).
//! Each sample starts from a simulator that has already taken a few steps, so that the step
//! measured is a typical one (its size chosen, its predictors warm); building it is outside
//! the timing.

use criterion::{criterion_group, criterion_main, BatchSize, Criterion};
use zeitner::{
    ConstrainedSystem, InnerMethod, MultiplierModel, Options, Simulator, Start, StepControl, Vector,
};
use zeitner_scenes::andrews::Andrews;
use zeitner_scenes::knife_edge::KnifeEdge;
use zeitner_scenes::pendulum::Pendulum;
use zeitner_scenes::steam_generator::SteamGenerator;

/// The methods timed, each as a user would set it.
fn methods() -> [(&'static str, Options); 5] {
    let adaptive = |method, multipliers| Options {
        method,
        multipliers,
        step: StepControl::adaptive(1e-8),
        ..Options::default()
    };
    [
        ("paper-rk4", Options::paper(1e-3)),
        ("default", Options::default()),
        (
            "dopri5-quadratic",
            adaptive(InnerMethod::DormandPrince54, MultiplierModel::Quadratic),
        ),
        (
            "dop853-every-stage",
            adaptive(InnerMethod::Dop853, MultiplierModel::EveryStage),
        ),
        (
            "esdirk54-quadratic",
            adaptive(InnerMethod::Esdirk54, MultiplierModel::Quadratic),
        ),
    ]
}

/// Steps taken before the one measured.
const WARM_UP_STEPS: usize = 5;

fn scene<S: ConstrainedSystem<N, Z>, const N: usize, const Z: usize>(
    c: &mut Criterion,
    name: &str,
    system: &S,
    start: Start<N>,
) {
    let mut group = c.benchmark_group(name);
    for (method, options) in methods() {
        group.bench_function(method, |b| {
            b.iter_batched_ref(
                || {
                    let mut sim = Simulator::new(system, start, options).expect("a valid start");
                    for _ in 0..WARM_UP_STEPS {
                        sim.step().expect("a step");
                    }
                    sim
                },
                |sim| sim.step().expect("a step"),
                BatchSize::SmallInput,
            );
        });
    }
    group.finish();
}

fn at_rest<const N: usize>(q: Vector<N>) -> Start<N> {
    Start {
        q,
        v: Vector::zeros(),
        t: 0.0,
    }
}

fn steps(c: &mut Criterion) {
    let pendulum = Pendulum {
        m: 1.0,
        length: 1.0,
        g: 9.81,
    };
    scene(
        c,
        "pendulum",
        &pendulum,
        at_rest(Vector::<2>::new(1.0, 0.0)),
    );
    scene(
        c,
        "steam_generator",
        &SteamGenerator::paper(),
        at_rest(Vector::<3>::zeros()),
    );
    scene(
        c,
        "andrews",
        &Andrews::published(),
        at_rest(Vector::from(Andrews::Q0)),
    );
    let edge = KnifeEdge::PAPER;
    let exact = edge.exact(2.0, 0.0);
    let start = Start {
        q: Vector::from(exact.q),
        v: Vector::from(exact.v),
        t: 0.0,
    };
    scene(c, "knife_edge", &edge, start);
}

criterion_group!(benches, steps);
criterion_main!(benches);
