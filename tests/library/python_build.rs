//! The Python package's test build shares the root's compiled
//! dependencies (`.ci/run` builds the wheel with python/Cargo.toml's `dev`
//! profile into the root's target directory): that holds only while the
//! two profiles build each dependency with the same settings, which this
//! suite checks from the two manifests. (The features the two turn on are
//! aligned by the root's `[build-dependencies]` and dev-dependencies;
//! docs/design.md, "Python package".)

use std::collections::BTreeMap;

/// The `[profile.dev]` of a manifest: its own settings and its package
/// tables by package name.
fn dev_profile(manifest: &str) -> (toml::Table, BTreeMap<String, toml::Value>) {
    let text = std::fs::read_to_string(manifest).unwrap();
    let doc: toml::Table = toml::from_str(&text).unwrap();
    let mut dev = doc["profile"]["dev"].as_table().unwrap().clone();
    let packages = dev
        .remove("package")
        .and_then(|p| p.as_table().cloned())
        .unwrap_or_default();
    (dev, packages.into_iter().collect())
}

/// The packages named in a lock file.
fn locked(lock: &str) -> Vec<String> {
    let text = std::fs::read_to_string(lock).unwrap();
    let doc: toml::Table = toml::from_str(&text).unwrap();
    doc["package"]
        .as_array()
        .unwrap()
        .iter()
        .map(|p| p["name"].as_str().unwrap().to_string())
        .collect()
}

#[test]
fn the_python_package_builds_the_shared_dependencies_as_the_root_does() {
    let (root, root_packages) = dev_profile("Cargo.toml");
    let (python, python_packages) = dev_profile("python/Cargo.toml");
    assert_eq!(root, python, "[profile.dev]'s own settings");
    let in_python = locked("python/Cargo.lock");
    for (name, settings) in &root_packages {
        if name == "*" || in_python.contains(name) {
            assert_eq!(
                python_packages.get(name),
                Some(settings),
                "[profile.dev.package.{name:?}] in python/Cargo.toml"
            );
        }
    }
    // The library itself is compiled anew for the wheel (other features):
    // it alone may differ, and every other table is the root's.
    for name in python_packages.keys() {
        assert!(
            root_packages.contains_key(name) || name == "slider-crank",
            "[profile.dev.package.{name:?}] in python/Cargo.toml only"
        );
    }
    assert!(root_packages.len() > 5 && in_python.contains(&"syn".to_string()));
}
