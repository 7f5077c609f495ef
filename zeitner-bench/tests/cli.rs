//! The benchmark as a user runs it: `work-precision --quick` on three scenes writes each scene's
//! CSV with the documented header and its figure.

use std::path::PathBuf;
use std::process::Command;

const HEADER: &str = "scene,method,setting,error_q,error_v,error_lambda,max_g,steps,newton_iterations,cpu_seconds,allocations";

#[test]
fn a_quick_work_precision_run_writes_its_tables_and_figures() {
    let dir: PathBuf = std::env::temp_dir().join(format!("zeitner-cli-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    let scenes = ["pendulum", "steam_generator", "andrews"];
    let status = Command::new(env!("CARGO_BIN_EXE_zeitner-bench"))
        .args(["work-precision", "--quick", "--scenes", &scenes.join(",")])
        .arg("--output-dir")
        .arg(&dir)
        .stdout(std::process::Stdio::null())
        .status()
        .expect("the benchmark starts");
    assert!(status.success(), "work-precision --quick failed: {status}");
    for scene in scenes {
        let csv = std::fs::read_to_string(dir.join(format!("{scene}.csv"))).expect("a CSV");
        let mut lines = csv.lines();
        assert_eq!(lines.next(), Some(HEADER), "{scene}");
        assert!(lines.next().is_some(), "{scene}: no rows");
        let png = std::fs::metadata(dir.join(format!("{scene}.png"))).expect("a figure");
        assert!(png.len() > 0, "{scene}: empty figure");
    }
    let _ = std::fs::remove_dir_all(&dir);
}
