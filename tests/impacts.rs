//! Gaps, impacts and events against closed forms: a ball dropped on a floor.

use zeitner::{
    ConstrainedSystem, DiagonalMass, MassKind, Matrix, Options, SceneSummary, Simulator,
    StopReason, Vector,
};

/// A ball of mass `m` above a floor: `y ≥ 0`, restitution `e`; written by hand.
struct Ball {
    m: f64,
    g: f64,
    e: f64,
}

impl ConstrainedSystem<1, 1> for Ball {
    const POSITION_CONSTRAINTS: usize = 1;
    const UNILATERAL_CONSTRAINTS: usize = 1;
    const MASS_IS_CONSTANT: bool = true;
    const DYNAMICS_DEPEND_ON_VELOCITY: bool = false;
    const SUMMARY: SceneSummary = SceneSummary {
        coordinates: 1,
        position_constraints: 1,
        velocity_constraints: 0,
        mass: MassKind::ConstantDiagonal,
        time_dependent: false,
        functions: &[],
    };
    type Mass = DiagonalMass<1>;
    fn mass_matrix(&self, _: &Vector<1>, _: f64) -> DiagonalMass<1> {
        DiagonalMass(Vector::from([self.m]))
    }
    fn applied_force(&self, _: &Vector<1>, _: &Vector<1>, _: f64) -> Vector<1> {
        Vector::from([-self.m * self.g])
    }
    fn constraint_residual(&self, q: &Vector<1>, _: &Vector<1>, _: f64) -> Vector<1> {
        *q
    }
    fn constraint_jacobian(&self, _: &Vector<1>, _: &Vector<1>, _: f64) -> Matrix<1, 1> {
        Matrix::identity()
    }
    fn constraint_rate(&self, _: &Vector<1>, v: &Vector<1>, _: f64) -> Vector<1> {
        *v
    }
    fn constraint_acceleration_bias(&self, _: &Vector<1>, _: &Vector<1>, _: f64) -> Vector<1> {
        Vector::zeros()
    }
    fn force_jacobians(
        &self,
        _: &Vector<1>,
        _: &Vector<1>,
        _: f64,
    ) -> (Matrix<1, 1>, Matrix<1, 1>) {
        (Matrix::zeros(), Matrix::zeros())
    }
    fn constraint_force_jacobians(
        &self,
        _: &Vector<1>,
        _: &Vector<1>,
        _: f64,
        _: &Vector<1>,
    ) -> (Matrix<1, 1>, Matrix<1, 1>) {
        (Matrix::zeros(), Matrix::zeros())
    }
    fn restitution(&self, _: usize) -> f64 {
        self.e
    }
}

#[test]
fn a_ball_bounces_at_the_closed_form_times() {
    let ball = Ball {
        m: 2.0,
        g: 9.81,
        e: 1.0,
    };
    let h0 = 1.0;
    let mut sim = Simulator::new(
        &ball,
        Vector::from([h0]),
        Vector::zeros(),
        0.0,
        Options::default(),
    )
    .unwrap();
    let fall = (2.0 * h0 / ball.g).sqrt();
    let mut impacts = Vec::new();
    sim.set_stop_time(10.0).unwrap();
    loop {
        let reason = sim.step().unwrap();
        if reason == StopReason::Impact {
            let impact = *sim.last_impact().unwrap();
            impacts.push((
                impact.t,
                impact.velocity_before[0],
                impact.velocity_after[0],
                impact.energy_lost,
            ));
        }
        if reason == StopReason::StopTimeReached {
            break;
        }
    }
    println!("{impacts:?}");
    for (n, (t, _, _, _)) in impacts.iter().enumerate() {
        let expected = fall * (1.0 + 2.0 * n as f64);
        assert!(
            (t - expected).abs() < 1e-9,
            "impact {n} at {t}, expected {expected}"
        );
    }
    assert_eq!(impacts.len(), 11);
}

mod common;
use common::contact::{Ball as GeneratedBall, FallingBar, WallPendulum};

#[test]
fn the_generated_ball_bounces_like_the_hand_written_one() {
    let ball = GeneratedBall {
        m: 2.0,
        g: 9.81,
        e: 1.0,
    };
    let mut sim = Simulator::new(
        &ball,
        Vector::from([1.0]),
        Vector::zeros(),
        0.0,
        Options::default(),
    )
    .unwrap();
    sim.set_stop_time(1.0).unwrap();
    let mut impacts = 0;
    while sim.step().unwrap() != StopReason::StopTimeReached {
        if let Some(impact) = sim.last_impact() {
            impacts += 1;
            assert!((impact.t - (2.0 / 9.81f64).sqrt()).abs() < 1e-10);
        }
    }
    assert!(impacts > 0);
}
