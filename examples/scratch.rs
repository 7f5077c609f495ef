#[path = "scenes/pendulum.rs"]
mod pendulum;
use zeitner::*;
fn main() {
    let scene = pendulum::Pendulum {
        m: 1.0,
        length: 1.0,
        g: 9.81,
    };
    for rtol in [1e-6, 1e-8, 1e-10] {
        let options = Options {
            step: StepControl::Adaptive {
                initial_step: 1e-3,
                min_step: 1e-12,
                max_step: 0.1,
                rtol,
                atol: rtol * 1e-2,
            },
            constraint_tolerance: 1e-12,
            ..Options::default()
        };
        let mut sim = Simulator::new(
            &scene,
            Vector::<2>::new(1.0, 0.0),
            Vector::zeros(),
            0.0,
            options,
        )
        .unwrap();
        let mut hs = vec![];
        sim.advance_to(1.0, |r| hs.push(r.end.t - r.start.t))
            .unwrap();
        let e = sim.last().end;
        println!(
            "rtol {rtol:e}: q {:?} steps {} stats {:?} hmin {:e} hmax {:e}",
            e.q,
            hs.len(),
            sim.statistics(),
            hs.iter().cloned().fold(1.0, f64::min),
            hs.iter().cloned().fold(0.0, f64::max)
        );
    }
    for n in [100, 1000] {
        let options = Options {
            method: InnerMethod::DormandPrince54,
            step: StepControl::Fixed {
                step: 1.0 / n as f64,
            },
            constraint_tolerance: 1e-12,
            ..Options::default()
        };
        let mut sim = Simulator::new(
            &scene,
            Vector::<2>::new(1.0, 0.0),
            Vector::zeros(),
            0.0,
            options,
        )
        .unwrap();
        sim.advance_to(1.0, |_| {}).unwrap();
        println!("fixed {n}: q {:?}", sim.last().end.q);
    }
}
