//! A study planned, run, interrupted by `kill -9`, resumed, sharded and gathered, on a function
//! whose outputs are known in closed form.

use std::collections::HashMap;
use std::io::Write as _;
use std::path::{Path, PathBuf};
use std::process::Command;
use std::time::{Duration, Instant};

use zeitner_study::{CaseTable, Parameter, RunSettings, Shard, Study, StudyError};

fn folder(name: &str) -> PathBuf {
    let folder = std::env::temp_dir().join(format!("zeitner-study-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&folder);
    folder
}

fn parameters() -> Vec<Parameter> {
    vec![
        Parameter::new("x", -1.0, 1.0),
        Parameter::new("y", 0.0, 2.0),
    ]
}

/// `x + y` and `x y`, failing where `x > 0.9` and panicking where `y > 1.95`; each run of a
/// case is logged (one line per run) where `log` is given, after `pause`.
fn study(
    log: Option<PathBuf>,
    pause: Duration,
) -> Study<impl Fn(&zeitner_study::Case) -> Result<[f64; 2], String> + Sync, 2> {
    let run = move |case: &zeitner_study::Case| {
        std::thread::sleep(pause);
        if let Some(log) = &log {
            let mut file = std::fs::OpenOptions::new()
                .append(true)
                .create(true)
                .open(log)
                .unwrap();
            // One write of the whole line: appends from several threads do not interleave.
            file.write_all(format!("{}\n", case.id).as_bytes()).unwrap();
        }
        let (x, y) = (case.get("x"), case.get("y"));
        assert!(y <= 1.95, "y = {y} is too large");
        if x > 0.9 {
            return Err(format!("x = {x} is too large"));
        }
        Ok([x + y, x * y])
    };
    Study::new(
        "closed-form",
        "x + y and x y",
        parameters(),
        ["sum", "product"],
        run,
    )
    .unwrap()
}

fn check_results(results: &zeitner_study::Results, table: &CaseTable) {
    assert_eq!(results.cases.len(), table.len());
    for (r, case) in results.cases.iter().enumerate() {
        assert_eq!(case.id, table.id(r));
        let [x, y] = [table.row(r)[0], table.row(r)[1]];
        assert_eq!(case.parameters, vec![x, y]);
        match &case.outcome {
            Ok(outputs) => assert_eq!(outputs, &vec![x + y, x * y]),
            Err(e) if y > 1.95 => assert_eq!(e, &format!("panicked: y = {y} is too large")),
            Err(e) => assert!(x > 0.9 && e == &format!("x = {x} is too large"), "{e}"),
        }
    }
}

#[test]
fn a_study_in_one_process_keeps_every_case_and_its_failures() {
    let folder = folder("whole");
    let study = study(None, Duration::ZERO);
    let table = CaseTable::grid(study.space(), &[21, 41]).unwrap();
    study.plan(&folder, &table, "grid 21x41", Some(50)).unwrap();
    let settings = RunSettings {
        progress: false,
        ..RunSettings::default()
    };
    let report = study.run(&folder, settings).unwrap();
    assert_eq!((report.batches_run, report.cases_run), (18, 861));
    // x > 0.9: the last grid value of x (1.0), 41 cases; y > 1.95: the last of y (2.0), 21 cases,
    // one of them also x = 1 (it panics before failing).
    assert_eq!(report.cases_failed, 41 + 21 - 1);
    let results = study.gather(&folder).unwrap();
    check_results(&results, &table);
    assert!(folder.join("results.parquet").exists());
    // Run again: nothing left to run.
    let again = study.run(&folder, settings).unwrap();
    assert_eq!((again.batches_kept, again.batches_run), (18, 0));
    std::fs::remove_dir_all(&folder).unwrap();
}

#[test]
fn shards_run_their_own_batches_and_gather_into_one_table() {
    let folder = folder("shards");
    let study = study(None, Duration::ZERO);
    let table = CaseTable::sobol(study.space(), 300, 3).unwrap();
    study
        .plan(&folder, &table, "sobol 300 seed 3", Some(7))
        .unwrap();
    let mut batches = 0;
    for index in 0..3 {
        let shard = Shard::new(index, 3).unwrap();
        assert!(matches!(
            study.gather(&folder),
            Err(StudyError::Incomplete { .. })
        ));
        let settings = RunSettings {
            shard,
            threads: Some(1),
            progress: false,
        };
        batches += study.run(&folder, settings).unwrap().batches_run;
    }
    assert_eq!(batches, 300_usize.div_ceil(7));
    check_results(&study.gather(&folder).unwrap(), &table);
    assert!(matches!(Shard::new(3, 3), Err(StudyError::BadShard { .. })));
    std::fs::remove_dir_all(&folder).unwrap();
}

#[test]
fn a_folder_is_never_resumed_with_another_study_or_an_edited_table() {
    let folder = folder("other");
    let study = study(None, Duration::ZERO);
    let table = CaseTable::grid(study.space(), &[3]).unwrap();
    study.plan(&folder, &table, "grid 3", None).unwrap();
    // The same plan again is a resume.
    study.plan(&folder, &table, "grid 3", None).unwrap();
    let other = CaseTable::grid(study.space(), &[4]).unwrap();
    let error = study.plan(&folder, &other, "grid 4", None).unwrap_err();
    assert!(
        matches!(&error, StudyError::DifferentStudy { planned, this, .. }
        if planned.contains("grid 3") && this.contains("grid 4")),
        "{error}"
    );
    let narrower = vec![
        Parameter::new("x", -1.0, 1.0),
        Parameter::new("y", 0.0, 3.0),
    ];
    let wider = Study::new(
        "closed-form",
        "x + y and x y",
        narrower,
        ["sum", "product"],
        |_: &zeitner_study::Case| Ok::<_, String>([0.0, 0.0]),
    )
    .unwrap();
    let settings = RunSettings {
        progress: false,
        ..RunSettings::default()
    };
    assert!(matches!(
        wider.run(&folder, settings),
        Err(StudyError::DifferentStudy { .. })
    ));
    let cases = folder.join("cases.csv");
    let text = std::fs::read_to_string(&cases)
        .unwrap()
        .replacen("0.0", "0.5", 1);
    std::fs::write(&cases, text).unwrap();
    assert!(matches!(
        study.run(&folder, settings),
        Err(StudyError::CasesChanged { .. })
    ));
    assert!(matches!(
        study.run(&folder.join("nowhere"), settings),
        Err(StudyError::NotPlanned { .. })
    ));
    std::fs::remove_dir_all(&folder).unwrap();
}

const CHILD: &str = "ZEITNER_STUDY_CHILD_FOLDER";

/// Not a test of its own: the process `kill -9` interrupts, started by the test below.
#[test]
#[ignore]
fn child_running_a_slow_study() {
    let Ok(folder) = std::env::var(CHILD) else {
        return;
    };
    let folder = PathBuf::from(folder);
    let study = study(Some(folder.join("runs.log")), Duration::from_millis(4));
    let settings = RunSettings {
        threads: Some(2),
        progress: false,
        ..RunSettings::default()
    };
    study.run(&folder, settings).unwrap();
}

fn parts(folder: &Path) -> Vec<String> {
    let mut names: Vec<String> = std::fs::read_dir(folder.join("parts"))
        .unwrap()
        .map(|e| e.unwrap().file_name().into_string().unwrap())
        .filter(|n| n.ends_with(".parquet"))
        .collect();
    names.sort();
    names
}

#[test]
fn a_study_killed_mid_run_resumes_keeping_every_finished_batch_and_running_none_twice() {
    let folder = folder("killed");
    let log = folder.join("runs.log");
    let slow = study(Some(log.clone()), Duration::from_millis(4));
    let table = CaseTable::grid(slow.space(), &[20, 15]).unwrap();
    slow.plan(&folder, &table, "grid 20x15", Some(10)).unwrap();
    let mut child = Command::new(std::env::current_exe().unwrap())
        .args([
            "--exact",
            "child_running_a_slow_study",
            "--ignored",
            "--nocapture",
        ])
        .env(CHILD, &folder)
        .spawn()
        .unwrap();
    let started = Instant::now();
    while parts(&folder).len() < 5 {
        assert!(
            started.elapsed() < Duration::from_secs(60),
            "the child never finished 5 batches"
        );
        std::thread::sleep(Duration::from_millis(2));
    }
    child.kill().unwrap(); // SIGKILL
    child.wait().unwrap();
    let finished = parts(&folder);
    assert!(
        finished.len() < 30,
        "the child finished before it was killed"
    );
    let runs_before = std::fs::read_to_string(&log).unwrap();
    let settings = RunSettings {
        progress: false,
        ..RunSettings::default()
    };
    let report = slow.run(&folder, settings).unwrap();
    assert_eq!(report.batches_kept, finished.len());
    assert_eq!(report.batches_run, 30 - finished.len());
    check_results(&slow.gather(&folder).unwrap(), &table);
    // Every case of a batch finished before the kill ran exactly once; the others at most twice
    // (once in the batch the kill cut short).
    let mut runs: HashMap<u64, usize> = HashMap::new();
    for line in std::fs::read_to_string(&log).unwrap().lines() {
        *runs.entry(line.parse().unwrap()).or_default() += 1;
    }
    assert_eq!(runs.len(), 300);
    for name in &finished {
        let batch: u64 = name["batch-".len()..name.len() - ".parquet".len()]
            .parse()
            .unwrap();
        for id in batch * 10..batch * 10 + 10 {
            assert_eq!(
                runs[&id], 1,
                "case {id} of finished batch {batch} ran again"
            );
        }
    }
    let rerun = runs.values().filter(|&&n| n == 2).count();
    assert!(runs.values().all(|&n| n <= 2));
    eprintln!(
        "killed after {} of 30 batches ({} case runs logged); resumed: {} batches kept, {} run, {rerun} cases of cut-short batches ran twice",
        finished.len(),
        runs_before.lines().count(),
        report.batches_kept,
        report.batches_run
    );
    std::fs::remove_dir_all(&folder).unwrap();
}
