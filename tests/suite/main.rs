//! Zeitner's integration tests, one module per subject, in one test binary: each binary
//! instantiates the integrator for every scene it uses, and twenty of them compiled the same
//! code twenty times (`cargo test --test suite pendulum::` runs one module).

mod common;

mod allocations;
mod andrews;
mod energy_drift;
mod errors;
mod every_stage;
mod generalized_alpha;
mod generated_derivatives;
mod high_order;
mod impacts;
mod nonholonomic;
mod pendulum;
mod redundant;
mod runtime_api;
mod sensitivities;
mod short_steps;
mod sparse;
mod stability;
mod steam_generator;
mod stiff_support;
mod structure;
