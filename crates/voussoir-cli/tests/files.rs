//! Issue 19, files that cannot be damaged, through the command line: `-o /dev/full` leaves the
//! device a device, an output naming the model is refused, and when one of several outputs
//! cannot be written none is.

use crate::common;
use crate::common::cwd::run;
use std::os::unix::fs::FileTypeExt;
use std::path::PathBuf;
use std::process::Output;

fn tmpdir(name: &str) -> PathBuf {
    common::tmpdir("files-cli", name)
}

fn arch(dir: &std::path::Path) -> String {
    let m = dir.join("arch.json");
    let o = run(&["gen", "arch", "--live", "full", "-o", m.to_str().unwrap()]);
    assert!(o.status.success());
    m.to_string_lossy().into_owned()
}

fn one_error_line(o: &Output) -> String {
    let e = String::from_utf8_lossy(&o.stderr).into_owned();
    assert!(!o.status.success());
    assert_eq!(e.trim_end().lines().count(), 1, "{e}");
    e
}

#[test]
fn limit_to_dev_full_leaves_the_device_a_device_and_exits_non_zero() {
    let d = tmpdir("full");
    let m = arch(&d);
    let o = run(&["limit", &m, "-o", "/dev/full"]);
    let e = one_error_line(&o);
    assert!(
        e.contains("/dev/full") && e.contains("not a regular file"),
        "{e}"
    );
    let meta = std::fs::metadata("/dev/full").unwrap();
    assert!(meta.file_type().is_char_device());
}

#[test]
fn an_output_naming_the_model_is_refused_and_the_model_kept() {
    let d = tmpdir("input");
    let m = arch(&d);
    let before = std::fs::read(&m).unwrap();
    let o = run(&["limit", &m, "-o", &m]);
    let e = one_error_line(&o);
    assert!(e.contains("is the input"), "{e}");
    assert_eq!(std::fs::read(&m).unwrap(), before);
}

#[test]
fn when_one_output_fails_no_output_is_written() {
    let d = tmpdir("all");
    let m = arch(&d);
    let svg = d.join("collapse.svg");
    let bad = d.join("no-such-dir").join("limit.json");
    let o = run(&[
        "limit",
        &m,
        "--svg",
        svg.to_str().unwrap(),
        "-o",
        bad.to_str().unwrap(),
    ]);
    one_error_line(&o);
    assert!(!svg.exists());
    let left: Vec<_> = std::fs::read_dir(&d)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .filter(|n| n.contains(".tmp"))
        .collect();
    assert!(left.is_empty(), "{left:?}");
}
