//! Peers run side by side with Zeitner: scripts in `zeitner-bench/peers/` that integrate the same
//! scenes and print their end states; errors are measured here, against the same references.

use std::path::{Path, PathBuf};
use std::process::Command;

/// One peer result: a tolerance setting and the end state it reached, or why it failed.
pub struct PeerRun {
    pub setting: String,
    pub outcome: Result<PeerEnd, String>,
}

pub struct PeerEnd {
    pub steps: u64,
    /// Right-hand-side evaluations, where the peer counts them (the in-process
    /// differential-equations peers): the floor's count of stages.
    pub stage_evaluations: Option<u64>,
    pub cpu_seconds: f64,
    pub max_g: f64,
    /// q, then v, then λ.
    pub values: Vec<f64>,
}

/// A peer: its name in the CSV, its script and the arguments before the scene.
pub struct Peer {
    pub name: &'static str,
    pub script: &'static str,
    pub leading_args: &'static [&'static str],
    /// Fixed-step peers take step counts; adaptive ones relative tolerances.
    pub fixed_steps: bool,
    /// Where its Python comes from.
    pub python: PeerPython,
    /// A fixed-step peer's step sizes, where the common ones are not its own (a first-order
    /// scheme reaches the errors of the others only with far smaller steps).
    pub step_sizes: Option<&'static [f64]>,
}

/// The Python a peer runs in.
#[derive(Clone, Copy, PartialEq, Eq)]
pub enum PeerPython {
    /// The virtual environment of [`python`] (pip's casadi and exudyn).
    Venv,
    /// The system's Python with a Debian package ([`debian_python`]).
    Debian {
        package: &'static str,
        module: &'static str,
    },
}

pub const PEERS: [Peer; 5] = [
    Peer {
        name: "peer-casadi-idas",
        script: "casadi_idas.py",
        leading_args: &["vm"],
        fixed_steps: false,
        python: PeerPython::Venv,
        step_sizes: None,
    },
    Peer {
        name: "peer-casadi-idas-c",
        script: "casadi_idas.py",
        leading_args: &["codegen"],
        fixed_steps: false,
        python: PeerPython::Venv,
        step_sizes: None,
    },
    Peer {
        name: "peer-exudyn-ga",
        script: "exudyn_ga.py",
        leading_args: &["ga"],
        fixed_steps: true,
        python: PeerPython::Venv,
        step_sizes: None,
    },
    Peer {
        name: "peer-exudyn-trapezoidal",
        script: "exudyn_ga.py",
        leading_args: &["trapezoidal"],
        fixed_steps: true,
        python: PeerPython::Venv,
        step_sizes: None,
    },
    Peer {
        name: "peer-siconos-moreau-jean",
        script: "siconos_friction.py",
        leading_args: &[],
        fixed_steps: true,
        python: PeerPython::Debian {
            package: "python3-siconos",
            module: "siconos.kernel",
        },
        // First order where a transition falls inside a step: the incline reaches 1e-6 only
        // with 1e-7 s steps (1.6e-6 at 1e-6 s).
        step_sizes: Some(&[1e-2, 1e-3, 1e-4, 1e-5, 1e-6, 1e-7]),
    },
];

/// The system's Python (`/usr/bin/python3`, where Debian installs its Python packages) with
/// `module` importable, installing `package` with apt-get on first use (as root, as on the
/// benchmark's machines). `Err` says why the peer is unavailable.
pub fn debian_python(package: &str, module: &str) -> Result<PathBuf, String> {
    let python = PathBuf::from("/usr/bin/python3");
    let ready = || {
        Command::new(&python)
            .args(["-c", &format!("import {module}")])
            .output()
            .map(|o| o.status.success())
            .unwrap_or(false)
    };
    if ready() {
        return Ok(python);
    }
    eprintln!("installing {package} with apt-get …");
    let installed = Command::new("sh")
        .args([
            "-c",
            &format!("apt-get update -qq && apt-get install -y -qq {package} > /dev/null"),
        ])
        .status();
    if !matches!(installed, Ok(s) if s.success()) {
        return Err(format!(
            "apt-get install {package} failed (Debian, as root, with its mirror reachable?)"
        ));
    }
    if ready() {
        Ok(python)
    } else {
        Err(format!(
            "{module} does not import after installing {package}"
        ))
    }
}

/// A Python with the peers installed, in a virtual environment under `dir`; created on first
/// use. `Err` says why the peers are unavailable.
pub fn python(dir: &Path) -> Result<PathBuf, String> {
    let venv = dir.join("peers-venv");
    let python = venv.join("bin/python");
    let ready = |python: &Path| {
        Command::new(python)
            .args(["-c", "import casadi, exudyn"])
            .output()
            .map(|o| o.status.success())
            .unwrap_or(false)
    };
    if ready(&python) {
        return Ok(python);
    }
    eprintln!(
        "installing the peers (casadi, exudyn) into {} …",
        venv.display()
    );
    let created = Command::new("python3")
        .args(["-m", "venv"])
        .arg(&venv)
        .status();
    if !matches!(created, Ok(s) if s.success()) {
        return Err("python3 -m venv failed (is Python 3 with venv installed?)".into());
    }
    let installed = Command::new(&python)
        .args([
            "-m",
            "pip",
            "install",
            "--quiet",
            "casadi==3.8.2",
            "exudyn==1.13.6",
        ])
        .status();
    if !matches!(installed, Ok(s) if s.success()) {
        return Err("pip install casadi exudyn failed (is PyPI reachable?)".into());
    }
    if ready(&python) {
        Ok(python)
    } else {
        Err("casadi or exudyn does not import after installation".into())
    }
}

/// Runs `peer` on `scene` for each setting (a relative tolerance or a step count); also the
/// wall seconds of its setup (model, integrators, code generation), where the script says.
pub fn run(
    python: &Path,
    peer: &Peer,
    scene: &str,
    t_end: f64,
    settings: &[f64],
    values: usize,
) -> (Vec<PeerRun>, Option<f64>) {
    let script = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("peers")
        .join(peer.script);
    let output = Command::new(python)
        .arg(&script)
        .args(peer.leading_args)
        .arg(scene)
        .arg(t_end.to_string())
        .args(settings.iter().map(|r| format!("{r:e}")))
        .output();
    let output = match output {
        Ok(output) => output,
        Err(error) => {
            let failure = PeerRun {
                setting: "all".into(),
                outcome: Err(format!("could not run {}: {error}", peer.script)),
            };
            return (vec![failure], None);
        }
    };
    let stdout = String::from_utf8_lossy(&output.stdout);
    let setup = stdout
        .lines()
        .find_map(|line| line.strip_prefix("SETUP,")?.trim().parse().ok());
    let runs = stdout
        .lines()
        .filter_map(|line| {
            let fields: Vec<&str> = line.split(',').collect();
            match fields.as_slice() {
                ["FAIL", setting, message @ ..] => Some(PeerRun {
                    setting: setting.to_string(),
                    outcome: Err(message.join(",")),
                }),
                ["ROW", setting, steps, cpu, max_g, rest @ ..] if rest.len() == values => {
                    let parsed: Option<Vec<f64>> = rest.iter().map(|x| x.parse().ok()).collect();
                    let end = (|| {
                        Some(PeerEnd {
                            stage_evaluations: None,
                            steps: steps.parse().ok()?,
                            cpu_seconds: cpu.parse().ok()?,
                            max_g: max_g.parse().ok()?,
                            values: parsed?,
                        })
                    })();
                    Some(PeerRun {
                        setting: setting.to_string(),
                        outcome: end.ok_or_else(|| format!("unreadable output: {line}")),
                    })
                }
                _ => None,
            }
        })
        .collect();
    (runs, setup)
}
