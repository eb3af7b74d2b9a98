//! The Python package's test build shares the root's compiled units, the
//! library among them (`.ci/run` builds the wheel with the test build's
//! settings and the library's default features into the root's target
//! directory): that holds only while the package is a member of the
//! root's workspace, with no profile of its own, and the wheel's profiles
//! are the root's, which this suite checks from the manifests. (The
//! features the two turn on in shared dependencies are aligned by the
//! root's `[build-dependencies]` and dev-dependencies; docs/design.md,
//! "Python package".)

/// A TOML file of the repository, parsed.
fn manifest(path: &str) -> toml::Table {
    let text = std::fs::read_to_string(path).unwrap();
    toml::from_str(&text).unwrap()
}

#[test]
fn the_python_package_is_a_member_of_the_root_workspace_without_profiles_of_its_own() {
    let root = manifest("Cargo.toml");
    let workspace = root["workspace"].as_table().unwrap();
    let members = workspace["members"].as_array().unwrap();
    assert!(members.iter().any(|m| m.as_str() == Some("python")));
    // The root crate alone is the default member: `cargo test` and
    // `cargo clippy --all-targets` at the root never build the bindings.
    assert!(!workspace.contains_key("default-members"));
    let python = manifest("python/Cargo.toml");
    // A table of either would make the package a workspace of its own or
    // be ignored (Cargo reads a member's profiles from the root only).
    assert!(
        !python.contains_key("workspace"),
        "[workspace] in python/Cargo.toml"
    );
    assert!(
        !python.contains_key("profile"),
        "[profile] in python/Cargo.toml"
    );
    assert!(
        !std::path::Path::new("python/Cargo.lock").exists(),
        "python/Cargo.lock: the workspace's lock file is the root's"
    );
}

#[test]
fn the_wheels_profiles_are_the_roots() {
    let profiles = manifest("Cargo.toml")["profile"]
        .as_table()
        .unwrap()
        .clone();
    let pyproject = manifest("python/pyproject.toml");
    let wheel = pyproject["tool"]["maturin"]["profile"].as_str().unwrap();
    let table = profiles[wheel].as_table().unwrap();
    assert_eq!(table["inherits"].as_str(), Some("release"));
    assert_eq!(table["lto"].as_str(), Some("thin"));
    // The wheel `.ci/run` tests: the `dev` profile (maturin's `cargo
    // rustc` builds `test` as a test harness), whose library is at the
    // test profile's level, and the library's default features, or the
    // library is compiled again.
    let ci = std::fs::read_to_string(".ci/run").unwrap();
    let args = (ci.lines())
        .find_map(|l| l.trim().strip_prefix("MATURIN_PEP517_ARGS=\""))
        .unwrap();
    assert!(args.starts_with("--profile dev "), "{args}");
    assert!(args.contains("test-build"), "{args}");
    let python = manifest("python/Cargo.toml");
    let features = python["features"]["test-build"].as_array().unwrap();
    assert!(
        features
            .iter()
            .any(|f| f.as_str() == Some("slider-crank/default"))
    );
    let test = profiles["test"].as_table().unwrap();
    let library = profiles["dev"]["package"]["slider-crank"]
        .as_table()
        .unwrap();
    assert_eq!(library.get("opt-level"), test.get("opt-level"));
    assert_eq!(test.len(), 1, "[profile.test] sets more than the level");
}
