//! The gallery against other processes: two galleries written into one
//! directory at once, and a gallery interrupted by Ctrl-C (SIGINT) in the
//! middle. The directory holds one whole gallery, old or new, and no
//! temporary file.

#![cfg(unix)]

use slider_crank::FigureName;
use slider_crank::gallery::Gallery;
use slider_crank::render::FileFormat;
use std::io::{BufRead, BufReader};
use std::path::Path;
use std::process::{Child, Command, Stdio};

const BIN: &str = env!("CARGO_BIN_EXE_slider-crank");

/// The figures of the galleries written here: enough work that a
/// gallery is still making files long after its first one.
const ONLY: &str = "fig-63-velocity,fig-66-kisch,fig-67-example,ng-fig-1-torque";

fn names() -> Vec<String> {
    let figures = ONLY.split(',').map(|n| FigureName::from_name(n).unwrap());
    Gallery::new()
        .with_figures(figures)
        .with_formats(FileFormat::ALL)
        .file_names()
}

/// Starts `gallery --out DIR --only …` and waits for its first progress
/// line (its first file made: it holds the directory by then).
fn start(dir: &Path) -> (Child, BufReader<std::process::ChildStderr>) {
    let mut child = Command::new(BIN)
        .args(["gallery", "--only", ONLY, "--out"])
        .arg(dir)
        .stdout(Stdio::null())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    let mut stderr = BufReader::new(child.stderr.take().unwrap());
    let mut line = String::new();
    stderr.read_line(&mut line).unwrap();
    assert!(line.starts_with("gallery: 1/"), "{line}");
    (child, stderr)
}

/// The temporary files left in `dir`.
fn leftovers(dir: &Path) -> Vec<String> {
    std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .filter(|n| n.starts_with(".slider-crank-"))
        .collect()
}

#[test]
fn a_second_gallery_into_the_same_directory_is_refused_while_the_first_writes() {
    let scratch = tempfile::tempdir().unwrap();
    let dir = scratch.path().join("gc");
    let (mut first, mut rest) = start(&dir);
    let second = Command::new(BIN)
        .args(["gallery", "--only", ONLY, "--out"])
        .arg(&dir)
        .output()
        .unwrap();
    let said = String::from_utf8_lossy(&second.stderr);
    assert_eq!(second.status.code(), Some(2), "{said}");
    assert!(
        said.starts_with("slider-crank: error: another slider-crank is writing the gallery in "),
        "{said}"
    );
    assert_eq!(said.lines().count(), 1, "{said}");
    let mut progress = String::new();
    std::io::Read::read_to_string(&mut rest, &mut progress).unwrap();
    assert!(first.wait().unwrap().success(), "{progress}");
    // What the first wrote is one whole gallery: --check finds every file
    // as this build makes it.
    let check = Command::new(BIN)
        .args(["gallery", "--check", "--only", ONLY, "--out"])
        .arg(&dir)
        .output()
        .unwrap();
    assert!(
        check.status.success(),
        "{}",
        String::from_utf8_lossy(&check.stdout)
    );
    assert!(leftovers(&dir).is_empty(), "{:?}", leftovers(&dir));
}

#[test]
fn an_interrupted_gallery_keeps_the_old_files_and_leaves_no_temporary_file() {
    use std::os::unix::process::ExitStatusExt;
    let scratch = tempfile::tempdir().unwrap();
    let dir = scratch.path().join("g");
    std::fs::create_dir(&dir).unwrap();
    let names = names();
    for name in &names {
        std::fs::write(dir.join(name), "old").unwrap();
    }
    let (mut child, _stderr) = start(&dir);
    let killed = Command::new("kill")
        .args(["-INT", &child.id().to_string()])
        .status()
        .unwrap();
    assert!(killed.success());
    let status = child.wait().unwrap();
    assert_eq!(status.signal(), Some(2), "ended by the SIGINT: {status:?}");
    assert!(leftovers(&dir).is_empty(), "{:?}", leftovers(&dir));
    // Not one file replaced: the gallery is replaced whole or not at all,
    // and it was interrupted long before its last file was made.
    let old: Vec<&String> = names
        .iter()
        .filter(|n| std::fs::read(dir.join(n)).unwrap() == b"old")
        .collect();
    assert_eq!(old.len(), names.len(), "replaced: some of {names:?}");
}
