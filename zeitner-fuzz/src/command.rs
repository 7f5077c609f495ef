//! `zeitner-fuzz`: the runtime fuzzer's watchdog and its worker.
//!
//! The parent runs the cases in a child process — this binary with the hidden `--worker` flag —
//! which prints `begin <seed>` before a case and one verdict line after it. A case that has not
//! finished within the timeout is recorded as a hang, the worker is killed and restarted after
//! it; a worker that dies inside a case is recorded as a crash. The worker catches panics and
//! reports them with their message. Every failure's seed replays with `--seed S --runs 1`
//! (`--trace` runs it in this process and prints the case and every call).

use std::collections::BTreeMap;
use std::io::{BufRead, BufReader, Write as _};
use std::panic::{self, AssertUnwindSafe};
use std::process::{Child, Command, Stdio};
use std::sync::mpsc::{self, Receiver, RecvTimeoutError};
use std::sync::Mutex;
use std::time::{Duration, Instant};
use zeitner::Float;

use indicatif::{ProgressBar, ProgressStyle};

use crate::accuracy::{self, AccuracyOutcome};
use crate::cases::{self, Budget, FailureClass};

/// Fuzzes the runtime: random scenes, starts, options and calls against its promises, each case
/// in a watched worker process; `--accuracy` counts silent wrong answers instead.
#[derive(clap::Parser)]
#[command(version, about)]
pub struct FuzzArgs {
    /// Cases to run.
    #[arg(long, default_value_t = 100_000)]
    runs: u64,
    /// The first case's seed; case k has seed S + k. Default: from the clock (printed).
    #[arg(long)]
    seed: Option<u64>,
    /// A case running longer than this is a hang.
    #[arg(long, default_value_t = 2000)]
    timeout_ms: u64,
    /// The accuracy fuzz: sensible options on scenes with references, counting silent wrong
    /// answers.
    #[arg(long)]
    accuracy: bool,
    /// Run in this process and print every case and every call (for replaying a seed).
    #[arg(long)]
    trace: bool,
    /// Each hang is run again alone with this timeout: one that finishes is recorded as slow
    /// (bounded, but over the timeout), one that does not stays a hang. 0: no second run.
    #[arg(long, default_value_t = 30_000)]
    recheck_ms: u64,
    /// Where to write every failure's seed and detail.
    #[arg(long, default_value = "target/zeitner/fuzz")]
    output_dir: std::path::PathBuf,
    /// Run as the watchdog's worker: `runs` cases from `seed`, verdicts on stdout.
    #[arg(long, hide = true)]
    worker: bool,
}

/// The fuzzer as the command line asks: the watchdog, its worker, or one traced case.
pub fn run(args: FuzzArgs) -> Result<(), Box<dyn std::error::Error>> {
    if args.worker {
        let seed = args.seed.ok_or("the worker needs --seed")?;
        return worker(seed, args.runs, args.accuracy);
    }
    fuzz(args)
}

/// One line of the worker's report on a case, made single-line.
fn line(text: &str) -> String {
    text.replace(['\n', '\r'], " ")
}

static PANIC_MESSAGE: Mutex<Option<String>> = Mutex::new(None);

/// Panics are caught: remember the message and location instead of printing them.
fn quiet_panics() {
    panic::set_hook(Box::new(|info| {
        let message = if let Some(s) = info.payload().downcast_ref::<&str>() {
            s.to_string()
        } else if let Some(s) = info.payload().downcast_ref::<String>() {
            s.clone()
        } else {
            "(non-string payload)".to_string()
        };
        let location = info
            .location()
            .map_or(String::new(), |l| format!(" at {}:{}", l.file(), l.line()));
        *PANIC_MESSAGE.lock().unwrap_or_else(|e| e.into_inner()) =
            Some(format!("{message}{location}"));
    }));
}

fn panic_message() -> String {
    PANIC_MESSAGE
        .lock()
        .unwrap_or_else(|e| e.into_inner())
        .take()
        .unwrap_or_default()
}

/// The worker: runs `runs` cases from `seed`, a `begin` line before each, a verdict after.
/// Robustness verdicts: `case <seed> <class|ok> <steps> <errors> <detail>`; accuracy verdicts:
/// `acc <seed> <ok|wrong|failed|panic> <scene> <rtol> <q> <v> <λ> <detail>`, with the errors
/// over their tolerances.
fn worker(seed: u64, runs: u64, accuracy: bool) -> Result<(), Box<dyn std::error::Error>> {
    quiet_panics();
    let stdout = std::io::stdout();
    let budget = Budget::default();
    for seed in seed..seed.saturating_add(runs) {
        writeln!(stdout.lock(), "begin {seed}")?;
        let verdict = if accuracy {
            accuracy_verdict(seed)
        } else {
            robustness_verdict(seed, &budget)
        };
        let mut out = stdout.lock();
        writeln!(out, "{}", line(&verdict))?;
        out.flush()?;
    }
    Ok(())
}

fn robustness_verdict(seed: u64, budget: &Budget) -> String {
    let result = panic::catch_unwind(AssertUnwindSafe(|| {
        let case = cases::generate(seed);
        cases::run(&case, budget, &mut |_| {})
    }));
    match result {
        Ok(outcome) => {
            let errors = if outcome.errors.is_empty() {
                "-".to_string()
            } else {
                outcome.errors.join(",")
            };
            let (class, detail) = outcome
                .failure
                .map_or(("ok", String::new()), |f| (f.class.name(), f.detail));
            let storage = format!(
                "{}{}{}{}",
                if outcome.sparse_storage {
                    "sparse"
                } else {
                    "dense"
                },
                if outcome.turned_implicit {
                    "+implicit"
                } else {
                    ""
                },
                if outcome.every_stage {
                    "+every-stage"
                } else {
                    ""
                },
                if outcome.half_explicit {
                    "+half-explicit"
                } else {
                    ""
                },
            );
            format!(
                "case {seed} {class} {} {storage} {errors} {detail}",
                outcome.steps
            )
        }
        Err(_) => format!("case {seed} panic 0 - {}", panic_message()),
    }
}

fn accuracy_verdict(seed: u64) -> String {
    let case = accuracy::generate(seed);
    let result = panic::catch_unwind(AssertUnwindSafe(|| accuracy::run(&case)));
    // The sparse storage's runs are a scene of their own in the summary.
    let storage = if case.disturbances.sparse_storage {
        "+sparse"
    } else {
        ""
    };
    let head = format!("{}{storage} {:e}", case.scene.name(), case.rtol());
    match result {
        Ok(outcome @ AccuracyOutcome::Ok { .. }) => {
            // `wrong` is empty unless a ratio is over the threshold (or NaN).
            let wrong = outcome.wrong();
            let verdict = if wrong.is_empty() { "ok" } else { "wrong" };
            let [q, v, lambda] = outcome.ratios();
            format!(
                "acc {seed} {verdict} {head} {q:e} {v:e} {lambda:e} {}",
                wrong.join(",")
            )
        }
        Ok(AccuracyOutcome::Failed(variant, error)) => {
            format!("acc {seed} failed {head} NaN NaN NaN {variant} {error}")
        }
        Err(_) => format!("acc {seed} panic {head} NaN NaN NaN {}", panic_message()),
    }
}

/// A running worker and the lines it prints.
struct Worker {
    child: Child,
    lines: Receiver<String>,
}

impl Worker {
    fn spawn(seed: u64, runs: u64, accuracy: bool) -> std::io::Result<Self> {
        let mut command = Command::new(std::env::current_exe()?);
        command
            .args(["--worker", "--seed", &seed.to_string()])
            .args(["--runs", &runs.to_string()])
            .stdin(Stdio::null())
            .stdout(Stdio::piped())
            .stderr(Stdio::null());
        if accuracy {
            command.arg("--accuracy");
        }
        let mut child = command.spawn()?;
        let stdout = child.stdout.take().expect("stdout is piped");
        let (sender, lines) = mpsc::channel();
        std::thread::spawn(move || {
            for line in BufReader::new(stdout).lines() {
                let Ok(line) = line else { break };
                if sender.send(line).is_err() {
                    break;
                }
            }
        });
        Ok(Worker { child, lines })
    }

    fn stop(mut self) {
        let _ = self.child.kill();
        let _ = self.child.wait();
    }
}

/// What the watchdog saw of one case.
enum Event {
    Verdict(String),
    Hang(u64),
    Crash(u64),
}

/// Runs `runs` cases from `first` in workers, restarting after a hang or a crash; calls
/// `on_event` for each case.
fn supervise(
    first: u64,
    runs: u64,
    accuracy: bool,
    timeout: Duration,
    mut on_event: impl FnMut(Event),
) -> Result<(), Box<dyn std::error::Error>> {
    let end = first.saturating_add(runs);
    let mut next = first;
    // Starting a worker and waiting for its next `begin` is not a case: a generous limit.
    let idle = Duration::from_secs(60);
    while next < end {
        let worker = Worker::spawn(next, end - next, accuracy)?;
        let mut running: Option<(u64, Instant)> = None;
        loop {
            let wait = match running {
                Some((_, since)) => timeout.saturating_sub(since.elapsed()),
                None => idle,
            };
            match worker.lines.recv_timeout(wait) {
                Ok(text) => {
                    if let Some(seed) = text.strip_prefix("begin ") {
                        running = Some((seed.trim().parse()?, Instant::now()));
                    } else {
                        let Some((seed, _)) = running.take() else {
                            continue;
                        };
                        next = seed + 1;
                        on_event(Event::Verdict(text));
                        if next >= end {
                            break;
                        }
                    }
                }
                Err(RecvTimeoutError::Timeout) => {
                    let Some((seed, _)) = running else {
                        return Err("the fuzz worker printed nothing for 60 s".into());
                    };
                    next = seed + 1;
                    on_event(Event::Hang(seed));
                    break;
                }
                Err(RecvTimeoutError::Disconnected) => {
                    if let Some((seed, _)) = running {
                        next = seed + 1;
                        on_event(Event::Crash(seed));
                    } else if next < end {
                        return Err(format!("the fuzz worker exited before case {next}").into());
                    }
                    break;
                }
            }
        }
        worker.stop();
    }
    Ok(())
}

/// Counts by name, and the failures by class.
#[derive(Default)]
struct Tally {
    runs: u64,
    steps: u64,
    ok: u64,
    /// Runs on the sparse storage, and their accepted steps.
    sparse_runs: u64,
    sparse_steps: u64,
    /// Runs in which `InnerMethod::Automatic` turned to its implicit method.
    turned_implicit: u64,
    /// Runs with the multipliers solved at every stage.
    every_stage: u64,
    /// Runs with the half-explicit HEM5 (among those at every stage).
    half_explicit: u64,
    /// Failure class (or `hang`, `crash`) → (seed, detail).
    failures: BTreeMap<String, Vec<(u64, String)>>,
    /// Typed errors by variant.
    errors: BTreeMap<String, u64>,
    /// Accuracy: (scene, error / tolerance of q, q', λ, seed, rtol) of every Ok run.
    ratios: Vec<(String, [Float; 3], u64, Float)>,
    /// Cases over the timeout that finished alone and whose options ask for that work (over
    /// 100 RK4 substeps or Newton integrations per step): not failures, listed.
    costly: Vec<(u64, String)>,
}

impl Tally {
    fn failure(&mut self, class: &str, seed: u64, detail: String) {
        self.failures
            .entry(class.to_string())
            .or_default()
            .push((seed, detail));
    }

    fn count(&self, class: &str) -> usize {
        self.failures.get(class).map_or(0, Vec::len)
    }

    fn failed(&self) -> usize {
        self.failures.values().map(Vec::len).sum()
    }

    fn record(&mut self, event: Event) {
        self.runs += 1;
        let text = match event {
            Event::Hang(seed) => return self.failure("hang", seed, String::new()),
            Event::Crash(seed) => return self.failure("crash", seed, String::new()),
            Event::Verdict(text) => text,
        };
        let fields: Vec<&str> = text.splitn(7, ' ').collect();
        match fields.as_slice() {
            ["case", seed, class, steps, storage, errors, rest @ ..] => {
                let seed = seed.parse().unwrap_or(u64::MAX);
                let steps = steps.parse::<u64>().unwrap_or(0);
                self.steps += steps;
                if storage.starts_with("sparse") {
                    self.sparse_runs += 1;
                    self.sparse_steps += steps;
                }
                if storage.contains("+implicit") {
                    self.turned_implicit += 1;
                }
                if storage.contains("+every-stage") {
                    self.every_stage += 1;
                }
                if storage.contains("+half-explicit") {
                    self.half_explicit += 1;
                }
                for error in errors.split(',').filter(|e| *e != "-") {
                    *self.errors.entry(error.to_string()).or_default() += 1;
                }
                let detail = rest.first().unwrap_or(&"").to_string();
                if *class == "ok" {
                    self.ok += 1;
                } else {
                    self.failure(class, seed, detail);
                }
            }
            ["acc", ..] => self.record_accuracy(&text),
            _ => self.failure("unreadable", u64::MAX, text.clone()),
        }
    }

    fn record_accuracy(&mut self, text: &str) {
        let fields: Vec<&str> = text.splitn(9, ' ').collect();
        let [_, seed, verdict, scene, rtol, eq, ev, el, rest @ ..] = fields.as_slice() else {
            return self.failure("unreadable", u64::MAX, text.to_string());
        };
        let seed = seed.parse().unwrap_or(u64::MAX);
        let rtol: Float = rtol.parse().unwrap_or(Float::NAN);
        let ratios = [eq, ev, el].map(|e| e.parse::<Float>().unwrap_or(Float::NAN));
        let detail = rest.first().unwrap_or(&"").to_string();
        match *verdict {
            "ok" | "wrong" => {
                self.ratios.push((scene.to_string(), ratios, seed, rtol));
                if *verdict == "ok" {
                    self.ok += 1;
                } else {
                    let describe = format!(
                        "{scene} rtol {rtol:e}: error / tolerance q {:e}, v {:e}, λ {:e} ({detail} wrong)",
                        ratios[0], ratios[1], ratios[2]
                    );
                    self.failure("silent-wrong-answer", seed, describe);
                }
            }
            "failed" => {
                // Loud, not silent: listed with its seed, apart from the wrong answers.
                let variant = detail.split(' ').next().unwrap_or("").to_string();
                *self.errors.entry(variant).or_default() += 1;
                self.failure(
                    "typed-error",
                    seed,
                    format!("{scene} rtol {rtol:e}: {detail}"),
                );
            }
            _ => self.failure("panic", seed, format!("{scene}: {detail}")),
        }
    }

    fn message(&self) -> String {
        let failures: Vec<String> = self
            .failures
            .iter()
            .map(|(class, list)| format!("{class} {}", list.len()))
            .collect();
        if failures.is_empty() {
            "no failures".to_string()
        } else {
            failures.join(", ")
        }
    }
}

/// A failure's detail with its numbers and vectors blanked and the state left out: failures
/// alike in everything but the numbers are one distinct failure.
fn signature(class: &str, detail: &str) -> String {
    let detail = detail.split(" (q = ").next().unwrap_or(detail);
    let detail = detail.split(": before").next().unwrap_or(detail);
    let mut blanked = String::new();
    let mut in_number = false;
    for c in detail.chars() {
        let numeric = c.is_ascii_digit()
            || (in_number && matches!(c, '.' | 'e' | '-' | '+'))
            || (c == '-' && !in_number);
        if numeric {
            if !in_number {
                blanked.push('#');
            }
            in_number = true;
        } else {
            in_number = false;
            blanked.push(c);
        }
    }
    while let Some(start) = blanked.find("[#") {
        let Some(length) = blanked[start..].find(']') else {
            break;
        };
        blanked.replace_range(start..start + length + 1, "<vector>");
    }
    let short: String = blanked.chars().take(200).collect();
    format!("{class}: {short}")
}

fn quantile(values: &mut [Float], q: Float) -> Float {
    if values.is_empty() {
        return Float::NAN;
    }
    values.sort_by(Float::total_cmp);
    values[((values.len() - 1) as Float * q).round() as usize]
}

fn summary(tally: &Tally, args: &FuzzArgs, first: u64, elapsed: Duration) -> String {
    let mut out = String::new();
    let kind = if args.accuracy {
        "accuracy fuzz"
    } else {
        "runtime fuzz"
    };
    out.push_str(&format!(
        "{kind}: {} runs from seed {first} in {:.1} s ({} passed, {} failed, {} costly); timeout \
         {} ms\n",
        tally.runs,
        elapsed.as_secs_f64(),
        tally.ok,
        tally.failed(),
        tally.costly.len(),
        args.timeout_ms
    ));
    if args.accuracy {
        out.push_str(&format!(
            "  silent wrong answers (error > {} × tolerance): {}\n  typed errors (loud failures): {}\n  panics: {}, hangs: {}, slow: {}, crashes: {}\n",
            accuracy::THRESHOLD,
            tally.count("silent-wrong-answer"),
            tally.count("typed-error"),
            tally.count("panic"),
            tally.count("hang"),
            tally.count("slow"),
            tally.count("crash")
        ));
        let mut scenes: Vec<&str> = tally.ratios.iter().map(|r| r.0.as_str()).collect();
        scenes.sort();
        scenes.dedup();
        out.push_str(
            "  error / tolerance of the Ok runs (median, 99th percentile, max) for q, q', λ:\n",
        );
        for scene in scenes {
            let mut cells = Vec::new();
            for k in 0..3 {
                let mut r: Vec<Float> = tally
                    .ratios
                    .iter()
                    .filter(|r| r.0 == scene)
                    .map(|r| r.1[k])
                    .collect();
                cells.push(format!(
                    "{:.2e} {:.2e} {:.2e}",
                    quantile(&mut r, 0.5),
                    quantile(&mut r, 0.99),
                    quantile(&mut r, 1.0)
                ));
            }
            let n = tally.ratios.iter().filter(|r| r.0 == scene).count();
            out.push_str(&format!("    {scene} ({n} runs): {}\n", cells.join(" | ")));
        }
        let mut worst: Vec<&(String, [Float; 3], u64, Float)> = tally.ratios.iter().collect();
        let largest = |r: &[Float; 3]| r.iter().copied().fold(0.0, Float::max);
        worst.sort_by(|a, b| largest(&b.1).total_cmp(&largest(&a.1)));
        out.push_str("  the largest error / tolerance (q, q', λ):\n");
        for (scene, r, seed, rtol) in worst.into_iter().take(8) {
            out.push_str(&format!(
                "    seed {seed}: {scene} rtol {rtol:.1e}: {:.2e} {:.2e} {:.2e}\n",
                r[0], r[1], r[2]
            ));
        }
    } else {
        out.push_str(&format!("  accepted steps: {}\n", tally.steps));
        out.push_str(&format!(
            "  on the sparse storage: {} runs, {} accepted steps\n",
            tally.sparse_runs, tally.sparse_steps
        ));
        out.push_str(&format!(
            "  runs in which `Automatic` turned implicit: {}\n",
            tally.turned_implicit
        ));
        out.push_str(&format!(
            "  runs with the multipliers solved at every stage: {} (half-explicit HEM5: {})\n",
            tally.every_stage, tally.half_explicit
        ));
        for class in FailureClass::ALL
            .iter()
            .map(|c| c.name())
            .chain(["hang", "slow", "crash"])
        {
            out.push_str(&format!("  {class}: {}\n", tally.count(class)));
        }
    }
    for (class, list) in &tally.failures {
        if !FailureClass::ALL.iter().any(|c| c.name() == class)
            && !matches!(
                class.as_str(),
                "hang" | "slow" | "crash" | "silent-wrong-answer" | "typed-error"
            )
        {
            out.push_str(&format!("  {class}: {}\n", list.len()));
        }
    }
    if !tally.costly.is_empty() {
        out.push_str(&format!(
            "  over the timeout with the work their options ask for (not failures): {}\n",
            tally.costly.len()
        ));
        for (seed, detail) in &tally.costly {
            out.push_str(&format!("    seed {seed}: {detail}\n"));
        }
    }
    out.push_str("  typed errors by variant:\n");
    for (variant, count) in &tally.errors {
        out.push_str(&format!("    {variant}: {count}\n"));
    }
    if !tally.failures.is_empty() {
        out.push_str("  distinct failures (numbers blanked), with their seeds:\n");
        let mut groups: BTreeMap<String, Vec<u64>> = BTreeMap::new();
        for (class, list) in &tally.failures {
            for (seed, detail) in list {
                groups
                    .entry(signature(class, detail))
                    .or_default()
                    .push(*seed);
            }
        }
        for (group, seeds) in &groups {
            let shown: Vec<String> = seeds.iter().take(50).map(u64::to_string).collect();
            let more = if seeds.len() > 50 {
                format!(" and {} more", seeds.len() - 50)
            } else {
                String::new()
            };
            out.push_str(&format!(
                "    [{}] {group}\n      seeds: {}{more}\n",
                seeds.len(),
                shown.join(" ")
            ));
        }
        out.push_str("  replay one: cargo run --release -p zeitner-fuzz --");
        if args.accuracy {
            out.push_str(" --accuracy");
        }
        out.push_str(" --seed S --runs 1 --trace\n");
    }
    out
}

/// Runs every hang again alone with the longer `recheck_ms` limit: a case that finishes then is
/// slow (bounded, but over the timeout), not a hang.
fn recheck_hangs(tally: &mut Tally, args: &FuzzArgs) -> Result<(), Box<dyn std::error::Error>> {
    if args.recheck_ms == 0 {
        return Ok(());
    }
    let hangs = tally.failures.remove("hang").unwrap_or_default();
    let limit = Duration::from_millis(args.recheck_ms);
    for (seed, _) in hangs {
        let clock = Instant::now();
        let mut verdict = None;
        supervise(seed, 1, args.accuracy, limit, |event| {
            if let Event::Verdict(text) = event {
                verdict = Some(text);
            }
        })?;
        match verdict {
            Some(text) => {
                let detail = format!(
                    "finished in {:.1} s when run alone: {text}",
                    clock.elapsed().as_secs_f64()
                );
                if !args.accuracy && cases::generate(seed).is_costly() {
                    tally.costly.push((seed, detail));
                } else {
                    tally.failure("slow", seed, detail);
                }
            }
            None => tally.failure(
                "hang",
                seed,
                format!("still running after {} ms when run alone", args.recheck_ms),
            ),
        }
    }
    Ok(())
}

/// Replays cases in this process, printing each case, every call and the outcome.
fn trace(args: &FuzzArgs, first: u64) {
    for seed in first..first.saturating_add(args.runs) {
        if args.accuracy {
            let case = accuracy::generate(seed);
            println!("{case}");
            println!("  outcome: {:?}", accuracy::run(&case));
            continue;
        }
        let case = cases::generate(seed);
        print!("{case}");
        if case.is_costly() {
            println!("  (costly options: over 100 RK4 substeps or Newton integrations per step)");
        }
        let clock = Instant::now();
        let outcome = cases::run(&case, &Budget::default(), &mut |line| {
            println!(
                "    [{:8.1} ms] {line}",
                clock.elapsed().as_secs_f64() * 1e3
            )
        });
        println!(
            "  outcome after {:.1} ms: {} steps, errors {:?}",
            clock.elapsed().as_secs_f64() * 1e3,
            outcome.steps,
            outcome.errors
        );
        match outcome.failure {
            Some(failure) => println!("  FAILURE {}: {}", failure.class.name(), failure.detail),
            None => println!("  no broken promise"),
        }
    }
}

fn fuzz(args: FuzzArgs) -> Result<(), Box<dyn std::error::Error>> {
    let first = args.seed.unwrap_or_else(|| {
        std::time::SystemTime::now()
            .duration_since(std::time::UNIX_EPOCH)
            .map_or(0, |d| d.as_secs())
    });
    if args.trace {
        trace(&args, first);
        return Ok(());
    }
    println!("fuzzing {} cases from seed {first}", args.runs);
    let progress = ProgressBar::new(args.runs).with_style(ProgressStyle::with_template(
        "{bar:40} {pos}/{len} {msg} [{elapsed} / {eta}]",
    )?);
    let clock = Instant::now();
    let mut tally = Tally::default();
    let timeout = Duration::from_millis(args.timeout_ms);
    supervise(first, args.runs, args.accuracy, timeout, |event| {
        tally.record(event);
        progress.inc(1);
        if tally.runs % 64 == 0 || tally.failed() > 0 {
            progress.set_message(tally.message());
        }
    })?;
    progress.finish_and_clear();
    recheck_hangs(&mut tally, &args)?;
    let text = summary(&tally, &args, first, clock.elapsed());
    print!("{text}");
    std::fs::create_dir_all(&args.output_dir)?;
    let name = if args.accuracy {
        "accuracy"
    } else {
        "robustness"
    };
    let mut log = text;
    log.push_str("\nevery failure:\n");
    for (class, list) in &tally.failures {
        for (seed, detail) in list {
            log.push_str(&format!("{class} {seed} {detail}\n"));
        }
    }
    let path = args.output_dir.join(format!("{name}-{first}.txt"));
    std::fs::write(&path, log)?;
    println!("wrote {}", path.display());
    Ok(())
}
