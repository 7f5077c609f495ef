//! A study: a function from a case's parameters to its outputs, run over a case table in
//! batches on every core, each finished batch kept on disk so that an interrupted run resumes
//! where it stopped, and split into shards for other machines.
//!
//! A study's folder:
//! - `manifest.json`: what the study is (its name and description — the scene and options —,
//!   the parameters with their ranges, the outputs, where the cases came from, their checksum,
//!   the batch size, this crate's version); a run refuses a folder planned for another study;
//! - `cases.csv`: the case table;
//! - `parts/batch-NNNNNN.parquet`: one per finished batch, renamed into place when complete;
//! - `results.parquet`: every batch gathered, in case order.

use core::fmt;
use std::panic::{catch_unwind, AssertUnwindSafe};
use std::path::{Path, PathBuf};
use std::time::Instant;

use indicatif::{ProgressBar, ProgressStyle};
use rayon::prelude::*;

use crate::parts::{self, CaseResult};
use crate::space::{Parameter, Space, SpaceError};
use crate::table::{CaseTable, TableError};

/// One case as the study function sees it: its id and its parameters' values. In [`Study`]'s
/// example.
pub struct Case<'a> {
    pub id: u64,
    values: &'a [f64],
    space: &'a Space,
}

impl Case<'_> {
    /// The value of parameter `name`. Panics (and the case is recorded as failed, naming the
    /// name) where the study has no such parameter.
    pub fn get(&self, name: &str) -> f64 {
        match self.space.index(name) {
            Some(i) => self.values[i],
            None => panic!("the study has no parameter `{name}`"),
        }
    }

    /// The values in the order the parameters were declared.
    pub fn values(&self) -> &[f64] {
        self.values
    }
}

/// A study with `K` outputs: `run_case` maps a case to them, or to an error that is recorded as
/// the case's result (a panic too) — a failed case never stops the study.
///
/// # Example
///
/// Planned, run and gathered in a folder: `x² + y` over a grid of 3 × 2 cases, and a case
/// that fails. The other types of the crate appear here: [`Parameter`], [`CaseTable`],
/// [`Case`], [`RunSettings`], [`Shard`], [`RunReport`], [`Results`] and [`CaseResult`].
///
/// ```
/// use zeitner_study::{Case, CaseTable, Parameter, RunSettings, Shard, Study};
///
/// let study = Study::new(
///     "square",
///     "x² + y, failing where x = 2",
///     vec![Parameter::new("x", 0.0, 2.0), Parameter::new("y", -1.0, 1.0)],
///     ["value"],
///     |case: &Case| {
///         let (x, y) = (case.get("x"), case.get("y"));
///         if x == 2.0 { Err(format!("x = {x}")) } else { Ok([x * x + y]) }
///     },
/// )?;
/// let table = CaseTable::grid(study.space(), &[3, 2])?;
/// let folder = std::env::temp_dir().join(format!("zeitner-study-doc-{}", std::process::id()));
/// study.plan(&folder, &table, "grid 3×2", None)?;
/// let settings = RunSettings { shard: Shard::ALL, threads: Some(1), progress: false };
/// let report = study.run(&folder, settings)?;
/// assert_eq!((report.cases_run, report.cases_failed), (6, 2));
/// let results = study.gather(&folder)?;
/// assert_eq!((results.cases.len(), results.failed()), (6, 2));
/// for case in &results.cases {
///     let (x, y) = (case.parameters[0], case.parameters[1]);
///     match &case.outcome {
///         Ok(value) => assert_eq!(value[0], x * x + y),
///         Err(error) => assert_eq!(error, "x = 2"),
///     }
/// }
/// std::fs::remove_dir_all(&folder)?;
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub struct Study<F, const K: usize> {
    name: String,
    description: String,
    space: Space,
    run_case: F,
}

/// What stops a study (a failed case does not).
///
/// ```
/// use zeitner_study::{Parameter, SpaceError, Study, StudyError};
///
/// let twice = vec![Parameter::new("x", 0.0, 1.0), Parameter::new("x", 0.0, 1.0)];
/// let study = Study::new("s", "", twice, ["y"], |_: &zeitner_study::Case| Ok::<_, String>([0.0]));
/// assert!(matches!(study, Err(StudyError::Space(SpaceError::Duplicate(name))) if name == "x"));
/// ```
#[derive(Debug)]
pub enum StudyError {
    Space(SpaceError),
    Table(TableError),
    /// The folder holds another study's manifest: what differs, as lines of each.
    DifferentStudy {
        folder: PathBuf,
        planned: String,
        this: String,
    },
    /// The folder has no `manifest.json`: nothing planned there.
    NotPlanned {
        folder: PathBuf,
    },
    /// `cases.csv` no longer matches the checksum in the manifest.
    CasesChanged {
        folder: PathBuf,
    },
    /// A shard `index/count` with `index ≥ count` or `count = 0`.
    BadShard {
        index: usize,
        count: usize,
    },
    /// Gathering found batches not yet run: how many, and the first.
    Incomplete {
        missing: usize,
        batches: usize,
        first: usize,
    },
    Io(String),
}

impl fmt::Display for StudyError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            StudyError::Space(e) => write!(f, "{e}"),
            StudyError::Table(e) => write!(f, "{e}"),
            StudyError::DifferentStudy {
                folder,
                planned,
                this,
            } => write!(
                f,
                "{} holds another study: its manifest has `{planned}` where this one has \
                 `{this}`; use another folder, or delete it to start afresh",
                folder.display()
            ),
            StudyError::NotPlanned { folder } => {
                write!(
                    f,
                    "{} holds no planned study (no manifest.json)",
                    folder.display()
                )
            }
            StudyError::CasesChanged { folder } => write!(
                f,
                "{}: cases.csv differs from the table its manifest was planned with",
                folder.display()
            ),
            StudyError::BadShard { index, count } => write!(
                f,
                "shard {index}/{count}: shards count from 0 and the index must be below the count"
            ),
            StudyError::Incomplete {
                missing,
                batches,
                first,
            } => write!(
                f,
                "{missing} of {batches} batches have not run yet (the first is batch {first}): \
                 run every shard before gathering"
            ),
            StudyError::Io(message) => write!(f, "{message}"),
        }
    }
}

impl std::error::Error for StudyError {}

impl From<SpaceError> for StudyError {
    fn from(e: SpaceError) -> Self {
        StudyError::Space(e)
    }
}

impl From<TableError> for StudyError {
    fn from(e: TableError) -> Self {
        StudyError::Table(e)
    }
}

fn io(path: &Path) -> impl Fn(std::io::Error) -> StudyError + '_ {
    move |e| StudyError::Io(format!("{}: {e}", path.display()))
}

/// Shard `index` of `count`: the batches `b` with `b % count == index`.
///
/// ```
/// use zeitner_study::{Shard, StudyError};
///
/// assert_eq!(Shard::new(1, 4)?, Shard { index: 1, count: 4 });
/// assert!(matches!(Shard::new(4, 4), Err(StudyError::BadShard { index: 4, count: 4 })));
/// # Ok::<(), StudyError>(())
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Shard {
    pub index: usize,
    pub count: usize,
}

impl Shard {
    pub const ALL: Shard = Shard { index: 0, count: 1 };

    pub fn new(index: usize, count: usize) -> Result<Self, StudyError> {
        if count == 0 || index >= count {
            return Err(StudyError::BadShard { index, count });
        }
        Ok(Shard { index, count })
    }
}

/// How a run goes: on how many threads (all cores if `None`), with a progress bar or not. In
/// [`Study`]'s example.
#[derive(Clone, Copy, Debug)]
pub struct RunSettings {
    pub shard: Shard,
    pub threads: Option<usize>,
    pub progress: bool,
}

impl Default for RunSettings {
    fn default() -> Self {
        RunSettings {
            shard: Shard::ALL,
            threads: None,
            progress: true,
        }
    }
}

/// What one run of a shard did. In [`Study`]'s example.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RunReport {
    /// Batches of the shard found finished by an earlier run, and left as they were.
    pub batches_kept: usize,
    pub batches_run: usize,
    pub cases_run: usize,
    pub cases_failed: usize,
    pub seconds: f64,
}

/// The gathered results with their column names. In [`Study`]'s example.
#[derive(Clone, Debug, PartialEq)]
pub struct Results {
    pub parameters: Vec<String>,
    pub outputs: Vec<String>,
    /// In the case table's order.
    pub cases: Vec<CaseResult>,
}

impl Results {
    pub fn failed(&self) -> usize {
        self.cases.iter().filter(|c| c.outcome.is_err()).count()
    }
}

impl<F, E, const K: usize> Study<F, K>
where
    F: Fn(&Case) -> Result<[f64; K], E> + Sync,
    E: fmt::Display,
{
    /// `name` and `description` (the scene, the options, anything that changes the results)
    /// are written in the manifest, so that a folder is never resumed with another study.
    pub fn new(
        name: &str,
        description: &str,
        parameters: Vec<Parameter>,
        outputs: [&str; K],
        run_case: F,
    ) -> Result<Self, StudyError> {
        Ok(Study {
            name: name.to_string(),
            description: description.to_string(),
            space: Space::new(parameters, &outputs)?,
            run_case,
        })
    }

    pub fn space(&self) -> &Space {
        &self.space
    }

    /// Runs one case as a study does: an error or a panic becomes the case's result.
    pub fn run_case(&self, id: u64, values: &[f64]) -> CaseResult {
        let case = Case {
            id,
            values,
            space: &self.space,
        };
        let outcome = match catch_unwind(AssertUnwindSafe(|| (self.run_case)(&case))) {
            Ok(Ok(outputs)) => Ok(outputs.to_vec()),
            Ok(Err(error)) => Err(error.to_string()),
            Err(panic) => Err(format!("panicked: {}", panic_text(&panic))),
        };
        CaseResult {
            id,
            parameters: values.to_vec(),
            outcome,
        }
    }

    /// Plans the study in `folder`: writes the case table and the manifest, unless the folder
    /// already holds this very study (then it is left as it is, to be resumed). `source` says
    /// where the cases came from ("grid 41×41", "sobol 1024 seed 7", a file name). Batches of
    /// `batch_size` cases, or by default about 64 batches and at most 1 000 cases each (a case
    /// of a small scene takes microseconds to milliseconds: tasks must be larger).
    pub fn plan(
        &self,
        folder: &Path,
        table: &CaseTable,
        source: &str,
        batch_size: Option<usize>,
    ) -> Result<(), StudyError> {
        let batch_size = batch_size
            .unwrap_or_else(|| table.len().div_ceil(64).clamp(1, 1000))
            .max(1);
        std::fs::create_dir_all(folder.join("parts")).map_err(io(folder))?;
        let cases_path = folder.join("cases.csv");
        let temporary = folder.join("cases.csv.partial");
        table.write_csv(&temporary).map_err(io(&temporary))?;
        let cases_text = std::fs::read(&temporary).map_err(io(&temporary))?;
        let manifest = self.manifest(table.len(), source, &cases_text, batch_size);
        let manifest_path = folder.join("manifest.json");
        if manifest_path.exists() {
            let planned = std::fs::read_to_string(&manifest_path).map_err(io(&manifest_path))?;
            std::fs::remove_file(&temporary).map_err(io(&temporary))?;
            return match first_difference(&planned, &manifest) {
                None => Ok(()),
                Some((planned, this)) => Err(StudyError::DifferentStudy {
                    folder: folder.to_path_buf(),
                    planned,
                    this,
                }),
            };
        }
        std::fs::rename(&temporary, &cases_path).map_err(io(&cases_path))?;
        let temporary = folder.join("manifest.json.partial");
        std::fs::write(&temporary, manifest).map_err(io(&temporary))?;
        std::fs::rename(&temporary, &manifest_path).map_err(io(&manifest_path))
    }

    /// Runs the batches of `settings.shard` that no earlier run finished.
    pub fn run(&self, folder: &Path, settings: RunSettings) -> Result<RunReport, StudyError> {
        let started = Instant::now();
        let (table, batch_size) = self.planned(folder)?;
        let batches = table.len().div_ceil(batch_size);
        let shard = settings.shard;
        let (done, pending): (Vec<usize>, Vec<usize>) = (shard.index..batches)
            .step_by(shard.count)
            .partition(|&b| part_path(folder, b).exists());
        let cases_of = |b: usize| b * batch_size..((b + 1) * batch_size).min(table.len());
        let total: usize = pending.iter().map(|&b| cases_of(b).len()).sum();
        let bar = if settings.progress {
            ProgressBar::new(total as u64)
        } else {
            ProgressBar::hidden()
        };
        bar.set_style(
            ProgressStyle::with_template(
                "{prefix} {wide_bar} {pos}/{len} cases, {elapsed} (eta {eta})",
            )
            .expect("a valid template"),
        );
        bar.set_prefix(format!(
            "{} shard {}/{}",
            self.name, shard.index, shard.count
        ));
        let run_batch = |&b: &usize| -> Result<usize, StudyError> {
            let rows: Vec<CaseResult> = cases_of(b)
                .map(|r| self.run_case(table.id(r), table.row(r)))
                .collect();
            let path = part_path(folder, b);
            parts::write(&path, &self.space, &rows).map_err(StudyError::Io)?;
            bar.inc(rows.len() as u64);
            Ok(rows.iter().filter(|r| r.outcome.is_err()).count())
        };
        let failed: Vec<usize> = match settings.threads {
            Some(threads) => rayon::ThreadPoolBuilder::new()
                .num_threads(threads)
                .build()
                .map_err(|e| StudyError::Io(e.to_string()))?
                .install(|| pending.par_iter().map(run_batch).collect::<Result<_, _>>())?,
            None => pending
                .par_iter()
                .map(run_batch)
                .collect::<Result<_, _>>()?,
        };
        bar.finish_and_clear();
        Ok(RunReport {
            batches_kept: done.len(),
            batches_run: pending.len(),
            cases_run: total,
            cases_failed: failed.iter().sum(),
            seconds: started.elapsed().as_secs_f64(),
        })
    }

    /// Gathers every batch into `results.parquet` (in case-table order) and returns them.
    pub fn gather(&self, folder: &Path) -> Result<Results, StudyError> {
        let (table, batch_size) = self.planned(folder)?;
        let batches = table.len().div_ceil(batch_size);
        let missing: Vec<usize> = (0..batches)
            .filter(|&b| !part_path(folder, b).exists())
            .collect();
        if let Some(&first) = missing.first() {
            return Err(StudyError::Incomplete {
                missing: missing.len(),
                batches,
                first,
            });
        }
        let mut cases = Vec::with_capacity(table.len());
        for b in 0..batches {
            cases.extend(parts::read(&part_path(folder, b), &self.space).map_err(StudyError::Io)?);
        }
        parts::write(&folder.join("results.parquet"), &self.space, &cases)
            .map_err(StudyError::Io)?;
        Ok(Results {
            parameters: self
                .space
                .parameters()
                .iter()
                .map(|p| p.name.clone())
                .collect(),
            outputs: self.space.outputs().to_vec(),
            cases,
        })
    }

    /// The planned table and batch size, checked against this study's manifest.
    fn planned(&self, folder: &Path) -> Result<(CaseTable, usize), StudyError> {
        let manifest_path = folder.join("manifest.json");
        if !manifest_path.exists() {
            return Err(StudyError::NotPlanned {
                folder: folder.to_path_buf(),
            });
        }
        let planned = std::fs::read_to_string(&manifest_path).map_err(io(&manifest_path))?;
        let field = |key: &str| -> Option<String> {
            let line = planned
                .lines()
                .find(|l| l.trim_start().starts_with(&format!("\"{key}\":")))?;
            let value = line.split_once(':')?.1.trim().trim_end_matches(',');
            Some(value.trim_matches('"').to_string())
        };
        let cases_path = folder.join("cases.csv");
        let cases_text = std::fs::read(&cases_path).map_err(io(&cases_path))?;
        if field("checksum") != Some(checksum(&cases_text)) {
            return Err(StudyError::CasesChanged {
                folder: folder.to_path_buf(),
            });
        }
        let table = CaseTable::read_csv(&self.space, &cases_path)?;
        let source = field("source").unwrap_or_default();
        let batch_size: usize = field("batch_size")
            .and_then(|b| b.parse().ok())
            .unwrap_or(0);
        let this = self.manifest(table.len(), &unescape(&source), &cases_text, batch_size);
        if let Some((planned, this)) = first_difference(&planned, &this) {
            return Err(StudyError::DifferentStudy {
                folder: folder.to_path_buf(),
                planned,
                this,
            });
        }
        Ok((table, batch_size.max(1)))
    }

    fn manifest(&self, cases: usize, source: &str, cases_text: &[u8], batch_size: usize) -> String {
        let mut text = String::from("{\n");
        text.push_str(&format!("  \"study\": \"{}\",\n", escape(&self.name)));
        text.push_str(&format!(
            "  \"description\": \"{}\",\n",
            escape(&self.description)
        ));
        text.push_str(&format!(
            "  \"zeitner_study_version\": \"{}\",\n",
            env!("CARGO_PKG_VERSION")
        ));
        text.push_str("  \"parameters\": [\n");
        let parameters = self.space.parameters();
        for (i, p) in parameters.iter().enumerate() {
            let comma = if i + 1 < parameters.len() { "," } else { "" };
            text.push_str(&format!(
                "    {{\"name\": \"{}\", \"low\": {:?}, \"high\": {:?}}}{comma}\n",
                p.name, p.low, p.high
            ));
        }
        text.push_str("  ],\n");
        let outputs: Vec<String> = self
            .space
            .outputs()
            .iter()
            .map(|o| format!("\"{o}\""))
            .collect();
        text.push_str(&format!("  \"outputs\": [{}],\n", outputs.join(", ")));
        text.push_str(&format!("  \"source\": \"{}\",\n", escape(source)));
        text.push_str(&format!("  \"cases\": {cases},\n"));
        text.push_str(&format!("  \"checksum\": \"{}\",\n", checksum(cases_text)));
        text.push_str(&format!("  \"batch_size\": {batch_size}\n"));
        text.push_str("}\n");
        text
    }
}

fn part_path(folder: &Path, batch: usize) -> PathBuf {
    folder
        .join("parts")
        .join(format!("batch-{batch:06}.parquet"))
}

/// FNV-1a, 64 bits: detects a case table edited after planning (not an adversary).
fn checksum(bytes: &[u8]) -> String {
    let hash = bytes.iter().fold(0xcbf2_9ce4_8422_2325_u64, |h, &b| {
        (h ^ u64::from(b)).wrapping_mul(0x0000_0100_0000_01b3)
    });
    format!("fnv1a64:{hash:016x}")
}

fn escape(text: &str) -> String {
    text.replace('\\', "\\\\")
        .replace('"', "\\\"")
        .replace('\n', "\\n")
}

fn unescape(text: &str) -> String {
    text.replace("\\n", "\n")
        .replace("\\\"", "\"")
        .replace("\\\\", "\\")
}

fn first_difference(planned: &str, this: &str) -> Option<(String, String)> {
    let mut a = planned.lines();
    let mut b = this.lines();
    loop {
        match (a.next(), b.next()) {
            (None, None) => return None,
            (x, y) if x == y => continue,
            (x, y) => {
                let text = |l: Option<&str>| l.unwrap_or("(nothing)").trim().to_string();
                return Some((text(x), text(y)));
            }
        }
    }
}

fn panic_text(panic: &Box<dyn std::any::Any + Send>) -> String {
    if let Some(s) = panic.downcast_ref::<&str>() {
        s.to_string()
    } else if let Some(s) = panic.downcast_ref::<String>() {
        s.clone()
    } else {
        "(no message)".into()
    }
}
