//! Outputs cannot damage files (issue 19): devices are never replaced, links are written
//! through, permissions are kept, an input is never overwritten, temporary files never stay
//! behind, and several outputs are written all or nothing.

use std::os::unix::fs::{FileTypeExt, PermissionsExt};
use std::path::{Path, PathBuf};
use voussoir_io::{write_all_or_nothing, write_atomic};

fn scratch(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("voussoir-files-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

fn leftovers(dir: &Path) -> Vec<String> {
    std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .filter(|n| n.contains(".tmp"))
        .collect()
}

#[test]
fn dev_full_stays_a_device_and_the_write_fails() {
    let p = Path::new("/dev/full");
    let before = std::fs::metadata(p).expect("/dev/full exists on Linux");
    assert!(before.file_type().is_char_device());
    let e = write_atomic(p, b"{}\n").unwrap_err();
    assert!(e.0.contains("not a regular file"), "{e}");
    assert!(std::fs::metadata(p).unwrap().file_type().is_char_device());
    // A directory is not replaced either.
    let d = scratch("dir");
    let e = write_atomic(&d, b"x").unwrap_err();
    assert!(e.0.contains("not a regular file"), "{e}");
    assert!(d.is_dir());
}

#[test]
fn a_link_is_written_through_and_permissions_are_kept() {
    let d = scratch("link");
    let real = d.join("real.json");
    std::fs::write(&real, "old").unwrap();
    std::fs::set_permissions(&real, std::fs::Permissions::from_mode(0o600)).unwrap();
    let link = d.join("link.json");
    std::os::unix::fs::symlink("real.json", &link).unwrap();
    write_atomic(&link, b"new").unwrap();
    assert!(std::fs::symlink_metadata(&link)
        .unwrap()
        .file_type()
        .is_symlink());
    assert_eq!(std::fs::read_to_string(&real).unwrap(), "new");
    let mode = std::fs::metadata(&real).unwrap().permissions().mode() & 0o777;
    assert_eq!(mode, 0o600);
    assert!(leftovers(&d).is_empty());
}

#[test]
fn an_output_that_is_an_input_is_refused_and_nothing_is_written() {
    let d = scratch("input");
    let model = d.join("model.json");
    std::fs::write(&model, "model").unwrap();
    let other = d.join("out.svg");
    let e = write_all_or_nothing(&[(&other, b"svg"), (&model, b"x")], &[&model]).unwrap_err();
    assert!(e.0.contains("is the input"), "{e}");
    assert_eq!(std::fs::read_to_string(&model).unwrap(), "model");
    assert!(!other.exists());
}

#[test]
fn when_one_output_fails_no_output_is_written_and_no_temporary_stays() {
    let d = scratch("all");
    let good = d.join("a.json");
    std::fs::write(&good, "before").unwrap();
    let bad = d.join("missing-dir").join("b.json");
    let e = write_all_or_nothing(&[(&good, b"after"), (&bad, b"x")], &[]).unwrap_err();
    assert!(e.0.contains("b.json"), "{e}");
    assert_eq!(std::fs::read_to_string(&good).unwrap(), "before");
    assert!(leftovers(&d).is_empty(), "{:?}", leftovers(&d));
    // Both fine: both written.
    let c = d.join("c.json");
    write_all_or_nothing(&[(&good, b"after"), (&c, b"c")], &[]).unwrap();
    assert_eq!(std::fs::read_to_string(&good).unwrap(), "after");
    assert_eq!(std::fs::read_to_string(&c).unwrap(), "c");
}
