//! Studies of a Zeitner scene — the paper's purpose, "a support to be studied in order to
//! optimise it": a table of cases in (a grid, a Sobol sample or a CSV file, checked against the
//! declared parameter ranges before anything runs), a table of results out (one row of scalars
//! per case in Parquet, a failed case's error kept as a value), every core busy, an interrupted
//! run resumed without recomputing a finished batch, and shards for other machines (a Dask
//! driver in `tools/dask_study.py`).
//!
//! - [`space`]: the parameters with their ranges, and the outputs;
//! - [`table`]: case tables and their checks;
//! - [`parts`]: results tables in Parquet;
//! - [`study`]: planning, running and gathering a study in its folder;
//! - [`cli`]: the command line of a study binary.

pub mod cli;
pub mod parts;
pub mod space;
pub mod study;
pub mod table;

pub use cli::StudyCommand;
pub use parts::CaseResult;
pub use space::{Parameter, Space, SpaceError};
pub use study::{Case, Results, RunReport, RunSettings, Shard, Study, StudyError};
pub use table::{CaseTable, TableError};
