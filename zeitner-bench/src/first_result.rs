//! Time to the first result: how long a user waits from an edited scene to its first
//! integration. For Zeitner, a crate holding just the scene and one run of it (default options
//! to the scene's end time) is rebuilt after its source is touched — the macro's expansion,
//! rustc and the link, with the runtime already built — and then run. The peers report their
//! own setup (model, integrator, code generation and compilation).

use std::path::{Path, PathBuf};
use std::process::Command;
use std::time::Instant;

/// One scene as a user's crate: where its model is written, how to build it and its start.
pub struct SceneCrate {
    pub scene: &'static str,
    pub source: Source,
    pub construct: &'static str,
    pub start: &'static str,
    pub t_end: f64,
}

/// Where a scene's model is written.
pub enum Source {
    /// A file of `zeitner-scenes/src/`, a module of the crate; the dense `Simulator` runs it.
    Example(&'static str),
    /// One invocation of the scaling families' macros (`zeitner-bench/src/scaling/families.rs`);
    /// `SparseSimulator` runs it, as the work-precision run does.
    Family(&'static str),
}

/// Zeitner's time to the first result of one scene: `(rebuild seconds, run seconds)`, wall
/// time; `Err` says what failed.
pub fn zeitner(scene: &SceneCrate, work: &Path) -> Result<(f64, f64), String> {
    let dir = work.join(scene.scene);
    let main_path = write_crate(scene, &dir)?;
    let target = work.join("target");
    let build = || {
        let output = Command::new(env!("CARGO"))
            .args(["build", "--release", "--quiet", "--manifest-path"])
            .arg(dir.join("Cargo.toml"))
            .env("CARGO_TARGET_DIR", &target)
            .output()
            .map_err(|e| format!("cargo: {e}"))?;
        if output.status.success() {
            Ok(())
        } else {
            Err(String::from_utf8_lossy(&output.stderr).into_owned())
        }
    };
    // The runtime and its dependencies once, untimed; then the scene's crate alone.
    build()?;
    let source = std::fs::read(&main_path).map_err(|e| e.to_string())?;
    std::fs::write(&main_path, source).map_err(|e| e.to_string())?;
    let clock = Instant::now();
    build()?;
    let compile = clock.elapsed().as_secs_f64();
    let binary: PathBuf = target
        .join("release")
        .join(format!("first-result-{}", scene.scene.replace('_', "-")));
    let clock = Instant::now();
    let run = Command::new(&binary)
        .output()
        .map_err(|e| format!("{}: {e}", binary.display()))?;
    let seconds = clock.elapsed().as_secs_f64();
    if !run.status.success() {
        return Err(String::from_utf8_lossy(&run.stderr).into_owned());
    }
    Ok((compile, seconds))
}

/// A user's crate for the scene in `dir`, as a user would write it: the model in the crate
/// itself (so that the timed rebuild expands and compiles it), Zeitner as a path dependency.
/// Returns the path of its `main.rs`.
fn write_crate(scene: &SceneCrate, dir: &Path) -> Result<PathBuf, String> {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"))
        .parent()
        .expect("the bench lives in the workspace");
    std::fs::create_dir_all(dir.join("src")).map_err(|e| e.to_string())?;
    let manifest = format!(
        "[package]\nname = \"first-result-{}\"\nversion = \"0.0.0\"\nedition = \"2021\"\n\n\
         [dependencies]\nzeitner = {{ path = {:?} }}\n\n[workspace]\n",
        scene.scene.replace('_', "-"),
        root.display().to_string()
    );
    std::fs::write(dir.join("Cargo.toml"), manifest).map_err(|e| e.to_string())?;
    // The workspace's lock file, so that the crate builds with the same dependencies.
    std::fs::copy(root.join("Cargo.lock"), dir.join("Cargo.lock")).map_err(|e| e.to_string())?;
    let (model, simulator) = match scene.source {
        Source::Example(file) => (
            format!(
                "#[allow(dead_code)]\nmod scenes {{\n    #[path = {path:?}]\n    pub mod {file};\n    \
                 pub mod reference {{\n        pub struct State<const N: usize, const Z: usize> {{\n            \
                 pub q: [f64; N],\n            pub v: [f64; N],\n            pub lambda: [f64; Z],\n        \
                 }}\n    }}\n}}\n\nuse zeitner::{{Options, Simulator, Start, Vector}};\n",
                path = root.join("zeitner-scenes/src").join(format!("{file}.rs")),
            ),
            "Simulator",
        ),
        Source::Family(invocation) => (
            format!(
                "#[macro_use]\n#[allow(dead_code)]\n#[path = {path:?}]\nmod families;\n\n\
                 #[allow(unused_imports)]\nuse families::{{horizontal_chain, ladder_span, sagging_ladder}};\n\
                 use zeitner::{{constrained_system, Options, SparseSimulator, Start, Vector}};\n\n{invocation}\n",
                path = root.join("zeitner-bench/src/scaling/families.rs"),
            ),
            "SparseSimulator",
        ),
    };
    let main = format!(
        "{model}\nfn main() {{\n    let scene = {construct};\n    let (q0, v0) = {start};\n    \
         let start = Start {{ q: q0, v: v0, t: 0.0 }};\n    \
         let mut sim = {simulator}::new(&scene, start, Options::default())\n        \
         .expect(\"a consistent start\");\n    sim.advance_to({t_end:?}, |_| {{}}).expect(\"a run\");\n    \
         println!(\"{{:?}}\", sim.last().end.q);\n}}\n",
        construct = scene.construct,
        start = scene.start,
        t_end = scene.t_end,
    );
    let main_path = dir.join("src/main.rs");
    std::fs::write(&main_path, main).map_err(|e| e.to_string())?;
    Ok(main_path)
}

/// The Markdown table of the first results: Zeitner's rebuild and run of each scene, and the
/// setup each peer reported. The in-process Rust peers share the bench's build and need no
/// setup of their own beyond constructing a solver (microseconds), so they have no column.
pub fn markdown(scenes: &[&SceneCrate], peer_setups: &[(&str, &str, f64)], work: &Path) -> String {
    use std::fmt::Write as _;
    let mut peers: Vec<&str> = peer_setups.iter().map(|(_, peer, _)| *peer).collect();
    peers.sort_unstable();
    peers.dedup();
    let mut out = String::from(
        "\n## Time to the first result\n\n\
         Wall seconds from an edited scene to its first result. Zeitner: a crate holding just the \
         scene and one run of it (default options, to the scene's end time; the chains and \
         ladders one invocation of their family's macro, run by `SparseSimulator`), rebuilt with \
         `cargo build --release` after its source was touched (the macro's expansion, rustc and \
         the link; the runtime built before), then run. Peers: the setup their script reports \
         (model and integrators built; for `-c`, CasADi's C code generation and gcc -O3 of each \
         tolerance's integrator, all tolerances of the run together). The in-process Rust peers \
         (diffsol, differential-equations) build with the bench, which an edited scene rebuilds as \
         it does Zeitner's, and construct their solvers in microseconds.\n\n",
    );
    let _ = write!(out, "| scene | Zeitner rebuild | Zeitner run |");
    peers.iter().for_each(|p| {
        let _ = write!(out, " `{p}` setup |");
    });
    let _ = writeln!(out, "\n|---|---|---|{}", "---|".repeat(peers.len()));
    for &scene in scenes {
        let name = scene.scene;
        let (rebuild, run) = match zeitner(scene, work) {
            Ok((rebuild, run)) => (format!("{rebuild:.2} s"), format!("{run:.3} s")),
            Err(failure) => {
                eprintln!("first result of {name} failed: {failure}");
                ("failed".into(), "–".into())
            }
        };
        let _ = write!(out, "| {name} | {rebuild} | {run} |");
        for peer in &peers {
            let setup = peer_setups
                .iter()
                .find(|(s, p, _)| *s == name && p == peer)
                .map_or("–".to_string(), |(_, _, seconds)| {
                    format!("{seconds:.2} s")
                });
            let _ = write!(out, " {setup} |");
        }
        out.push('\n');
    }
    out.push('\n');
    out
}
