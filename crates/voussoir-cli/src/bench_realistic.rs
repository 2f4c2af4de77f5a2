//! `voussoir bench --scenario realistic`: the models engineers build (issue 29 item 6) × the
//! analyses they run, each cell timed as a user meets it.
//!
//! Every cell runs this very binary as a child process (`voussoir limit model.json -o r.json`,
//! with the command's own defaults: no `--method` unless the bench was given one), so that the
//! time, the method that answered (after any fallback) and the certificate are exactly what the
//! command gives. A child process also gives each cell its own peak memory (the kernel's
//! `ru_maxrss` of the child, by `wait4`) and a time limit that cannot hang the benchmark: a cell
//! that runs longer than `--cell-time-limit` is killed and recorded as "timed out after N s".
//!
//! The models are generated (`voussoir gen …`) or imported (the LACT3 drawings, `voussoir
//! import`) into a scratch directory first; that time is not part of any cell.

use crate::common::Fail;
use serde::Serialize;
use serde_json::Value;
use std::fmt::Write as _;
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

/// The analyses of the realistic benchmark, in table order.
pub const ANALYSES: [&str; 6] = [
    "limit",
    "settle",
    "capacity",
    "safety",
    "least-thickness",
    "tilt",
];

/// Where a model comes from.
#[derive(Clone, Debug)]
enum Source {
    /// `voussoir gen ARGS`; `live` are the flags of the loaded variant (for limit and capacity),
    /// `dead` those of the variant without live loads.
    Gen {
        args: Vec<String>,
        live: Vec<String>,
        dead: Vec<String>,
    },
    /// A LACT3 drawing (file name in the LACT3 folder), imported in mm.
    Dxf(&'static str),
}

/// One model of the benchmark.
#[derive(Clone, Debug)]
pub struct ModelDef {
    pub name: String,
    pub description: String,
    source: Source,
    /// Flags given to every analysis (joint laws).
    flags: Vec<String>,
    /// The support motion of `settle` and `capacity` (None: the reason why not).
    motion: std::result::Result<Vec<String>, &'static str>,
    /// `least-thickness` arguments (generator and its flags), where it applies.
    least_thickness: Option<Vec<String>>,
}

fn s(v: &[&str]) -> Vec<String> {
    v.iter().map(|x| x.to_string()).collect()
}

/// The models of issue 29 item 6, in table order.
pub fn models() -> Vec<ModelDef> {
    let mut out = vec![ModelDef {
        name: "arch".into(),
        description: "the paper's arch (gen arch: 64 voussoirs; live load on the whole span)"
            .into(),
        source: Source::Gen {
            args: s(&["arch"]),
            live: s(&["--live", "full"]),
            dead: s(&["--live", "none"]),
        },
        flags: vec![],
        motion: Ok(s(&["--move", "right=0.01,-0.005"])),
        least_thickness: Some(s(&["arch"])),
    }];
    for (name, file, what) in [
        (
            "lact3-arch",
            "arch_1.dxf",
            "LACT3 arch_1.dxf (25 voussoirs)",
        ),
        ("lact3-portal", "Portal.dxf", "LACT3 Portal.dxf (40 blocks)"),
        ("lact3-wall", "wall.dxf", "LACT3 wall.dxf (182 bricks)"),
    ] {
        out.push(ModelDef {
            name: name.into(),
            description: format!(
                "{what}, tilting-table load; settle: the right half of the base 1 cm down"
            ),
            source: Source::Dxf(file),
            flags: vec![],
            // Filled in once the drawing is imported (the base is cut at its middle).
            motion: Err("the drawing is not imported yet"),
            least_thickness: None,
        });
    }
    for element in ["0.5", "0.25"] {
        for mesh in ["grid", "running-bond"] {
            for friction in [false, true] {
                let mut name = format!(
                    "facade-{}-{element}",
                    if mesh == "grid" { "grid" } else { "rb" }
                );
                let mut flags = vec![];
                if friction {
                    name.push_str("-mu0.6");
                    flags = s(&["--friction", "0.6", "--non-associative"]);
                }
                out.push(ModelDef {
                    name,
                    description: format!(
                        "the church façade of Fig 18, {mesh} of {element} m{}; settle: the right half 20 cm down",
                        if friction {
                            ", μ = 0.6 non-associative"
                        } else {
                            ""
                        }
                    ),
                    source: Source::Gen {
                        args: s(&["facade", "--mesh", mesh, "--element", element]),
                        live: s(&["--live", "horizontal"]),
                        dead: s(&["--live", "none"]),
                    },
                    flags,
                    motion: Ok(s(&["--profile", "uniform:11,22,-0.2"])),
                    least_thickness: None,
                });
            }
        }
    }
    out.push(ModelDef {
        name: "vault".into(),
        description: "the README's vault (gen vault --depth 1 --rings 3: 192 blocks); settle: the right springing 1 cm out, 0.5 cm down".into(),
        source: Source::Gen {
            args: s(&["vault", "--depth", "1", "--rings", "3"]),
            live: s(&["--live", "full"]),
            dead: s(&["--live", "none"]),
        },
        flags: vec![],
        motion: Ok(s(&["--move", "right=0.01,0,-0.005"])),
        least_thickness: None,
    });
    for n in [24usize, 48] {
        let quarter: Vec<String> = (0..n / 4)
            .flat_map(|k| ["--move".to_string(), format!("base{k}=0,0,-0.02")])
            .collect();
        let geometry = vec![
            "--radius".to_string(),
            "5".into(),
            "--thickness".into(),
            "0.3".into(),
            "--courses".into(),
            n.to_string(),
            "--segments".into(),
            n.to_string(),
        ];
        let mut args = vec!["dome".to_string()];
        args.extend(geometry.clone());
        let mut lt = vec!["dome".to_string()];
        lt.extend(geometry);
        out.push(ModelDef {
            name: format!("dome-{n}x{n}"),
            description: format!(
                "hemispherical dome R = 5 m, t = 0.3 m (t/R = 0.06), {n} courses × {n} segments; limit: 10 kN at the crown; settle: a quarter of the supports 2 cm down"
            ),
            source: Source::Gen {
                args,
                live: s(&["--crown-load", "10"]),
                dead: vec![],
            },
            flags: vec![],
            motion: Ok(quarter),
            least_thickness: Some(lt),
        });
    }
    out.push(ModelDef {
        name: "u-walls".into(),
        description: "gen walls --plan U (bonded corners, out-of-plane load on the main wall)"
            .into(),
        source: Source::Gen {
            args: s(&["walls", "--plan", "U"]),
            live: vec![],
            dead: s(&["--live", "none"]),
        },
        flags: vec![],
        motion: Err("one support (ground): no settlement defined"),
        least_thickness: None,
    });
    out
}

/// One cell of the table.
#[derive(Clone, Debug, Serialize)]
pub struct Cell {
    pub model: String,
    pub dim: u8,
    pub blocks: usize,
    pub analysis: String,
    /// `ok`, `failed`, `timed out`, `n/a`.
    pub outcome: String,
    /// The command as run (binary name `voussoir`, paths relative to the scratch directory).
    pub command: String,
    pub wall_s: Option<f64>,
    /// User + system CPU time of the child, s.
    pub cpu_s: Option<f64>,
    pub peak_mib: Option<f64>,
    /// One-minute load average of the machine when the cell started.
    pub load: Option<f64>,
    /// The method that produced the result (after any fallback).
    pub method: Option<String>,
    /// Methods that failed before it (`method: why`).
    pub tried: Vec<String>,
    pub gap: Option<f64>,
    pub admissibility: Option<f64>,
    /// The certificate's verdict where the command reports one; `None` where it reports none.
    /// An analysis of many programs (`safety`) reports, per kind of program and method, how its
    /// programs were answered (`answered`): the verdict is then whether every program was
    /// answered certified or decided (infeasible, unbounded), a `not certified` answer counting
    /// as re-solved by the next line of the same kind ([`answered_certified`]).
    pub certified: Option<bool>,
    /// The command's `answered` lines (kind of program, method, answers, outcome, why), where it
    /// reports them.
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub programs: Vec<ProgramLine>,
    /// The key number: λ (limit), the dead loads' work (settle), λ at the largest settlement
    /// (capacity), the geometric safety factor (safety), the thickness (least-thickness), the
    /// tilt angle in degrees (tilt).
    pub value: Option<f64>,
    /// The key number in words, or the error line.
    pub result: String,
}

/// One line of a command's `answered`: one method's answers to one kind of program.
#[derive(Clone, Debug, Serialize)]
pub struct ProgramLine {
    pub programs: String,
    pub method: String,
    pub answers: u64,
    pub outcome: String,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub why: Option<String>,
}

/// The command's `answered` lines, or none where it reports none.
fn program_lines(v: &Value) -> Vec<ProgramLine> {
    v["answered"].as_array().map_or(vec![], |a| {
        a.iter()
            .map(|l| ProgramLine {
                programs: l["programs"].as_str().unwrap_or("").to_string(),
                method: l["method"].as_str().unwrap_or("").to_string(),
                answers: l["answers"].as_u64().unwrap_or(0),
                outcome: l["outcome"].as_str().unwrap_or("").to_string(),
                why: l["why"].as_str().map(str::to_string),
            })
            .collect()
    })
}

/// Whether every program of an analysis of many programs was answered with a certificate:
/// each line `certified`, `infeasible` or `unbounded` (a decision with its certificate), and
/// every `not certified` answer re-solved by a later decided line of the same kind. An unknown
/// outcome, or a `not certified` answer no later line of its kind covers, is not certified.
pub fn answered_certified(lines: &[ProgramLine]) -> bool {
    voussoir::lp::outcomes_certified(
        lines
            .iter()
            .map(|l| (l.programs.as_str(), l.answers, l.outcome.as_str())),
    )
}

/// Benchmark settings.
pub struct Config {
    pub models: Option<Vec<String>>,
    pub analyses: Option<Vec<String>>,
    pub max_blocks: Option<usize>,
    pub cell_time_limit: f64,
    /// The limit counts the cell's CPU seconds (user + system) instead of wall-clock seconds:
    /// on a machine shared with other work the wall clock measures the others too.
    pub limit_cpu: bool,
    pub method: Option<String>,
    pub lact3: Option<PathBuf>,
    pub workdir: Option<PathBuf>,
    pub output: Option<PathBuf>,
}

/// The LACT3 folder: `--lact3`, else the repository's fixtures or the shared data, looked for
/// from the working directory up.
fn lact3_dir(given: &Option<PathBuf>) -> Result<PathBuf, Fail> {
    if let Some(d) = given {
        // Absolute: the cells run in their own scratch folders, where a relative folder named
        // nothing ("cannot read …/arch_1.dxf", the whole benchmark ended; session 23).
        return if d.is_dir() {
            std::fs::canonicalize(d).map_err(|e| Fail(format!("--lact3 {}: {e}", d.display())))
        } else {
            Err(Fail(format!("--lact3 {}: not a directory", d.display())))
        };
    }
    let here = std::env::current_dir().map_err(|e| Fail(format!("working directory: {e}")))?;
    for base in here.ancestors() {
        for rel in [
            "crates/voussoir-io/tests/fixtures/lact3",
            "shared/data/lact3",
            "../shared/data/lact3",
        ] {
            let d = base.join(rel);
            if d.join("arch_1.dxf").is_file() {
                return Ok(d);
            }
        }
    }
    Err(Fail(
        "the LACT3 drawings (arch_1.dxf, Portal.dxf, wall.dxf) were not found: run from the repository (crates/voussoir-io/tests/fixtures/lact3) or give --lact3 DIR, or leave the lact3-* models out with --models".into(),
    ))
}

/// What a finished child left.
struct Run {
    status: Option<i32>,
    timed_out: bool,
    wall: f64,
    cpu: f64,
    peak_mib: f64,
    stderr: String,
}

/// Run `exe ARGS` in `dir`, killed after `limit` seconds.
fn run_child(
    exe: &Path,
    args: &[String],
    dir: &Path,
    limit: f64,
    limit_cpu: bool,
    stdout: Option<&Path>,
) -> Result<Run, Fail> {
    let out = match stdout {
        Some(p) => Stdio::from(
            std::fs::File::create(p).map_err(|e| Fail(format!("{}: {e}", p.display())))?,
        ),
        None => Stdio::null(),
    };
    let err_path = dir.join("stderr.txt");
    let err_file = std::fs::File::create(&err_path)
        .map_err(|e| Fail(format!("{}: {e}", err_path.display())))?;
    let t0 = Instant::now();
    let mut child = Command::new(exe)
        .args(args)
        .current_dir(dir)
        .stdin(Stdio::null())
        .stdout(out)
        .stderr(err_file)
        .spawn()
        .map_err(|e| Fail(format!("cannot run {}: {e}", exe.display())))?;
    let pid = child.id() as libc::pid_t;
    let mut timed_out = false;
    let (status, usage) = loop {
        // The limit first: a cell is "timed out" once its time is up, whether or not it ends
        // in the same instant.
        let spent = if limit_cpu {
            cpu_seconds(pid)
        } else {
            t0.elapsed().as_secs_f64()
        };
        if !timed_out && spent > limit {
            timed_out = true;
            let _ = child.kill();
        }
        let mut st: libc::c_int = 0;
        // SAFETY: plain wait4 on our own child with valid out-pointers.
        let mut ru: libc::rusage = unsafe { std::mem::zeroed() };
        let r = unsafe { libc::wait4(pid, &mut st, libc::WNOHANG, &mut ru) };
        if r == pid {
            break (st, ru);
        }
        if r < 0 {
            return Err(Fail(format!(
                "waiting for the cell's process: {}",
                std::io::Error::last_os_error()
            )));
        }
        std::thread::sleep(Duration::from_millis(20));
    };
    let wall = t0.elapsed().as_secs_f64();
    let tv = |t: libc::timeval| t.tv_sec as f64 + t.tv_usec as f64 * 1e-6;
    let exited = libc::WIFEXITED(status);
    Ok(Run {
        status: exited.then(|| libc::WEXITSTATUS(status)),
        timed_out,
        wall,
        cpu: tv(usage.ru_utime) + tv(usage.ru_stime),
        // Linux reports ru_maxrss in KiB.
        peak_mib: usage.ru_maxrss as f64 / 1024.0,
        stderr: std::fs::read_to_string(&err_path).unwrap_or_default(),
    })
}

/// CPU seconds (user + system) a running process has used so far (`/proc/PID/stat`); 0 where
/// that cannot be read.
fn cpu_seconds(pid: libc::pid_t) -> f64 {
    let Ok(stat) = std::fs::read_to_string(format!("/proc/{pid}/stat")) else {
        return 0.0;
    };
    // Fields after the command name (which is in parentheses and may hold spaces): state is
    // field 3, utime and stime fields 14 and 15.
    let Some(rest) = stat.rsplit_once(')').map(|(_, r)| r) else {
        return 0.0;
    };
    let f: Vec<&str> = rest.split_whitespace().collect();
    let ticks = |i: usize| f.get(i).and_then(|v| v.parse::<f64>().ok()).unwrap_or(0.0);
    // SAFETY: sysconf has no preconditions.
    let hz = unsafe { libc::sysconf(libc::_SC_CLK_TCK) }.max(1) as f64;
    (ticks(11) + ticks(12)) / hz
}

fn load_average() -> Option<f64> {
    std::fs::read_to_string("/proc/loadavg")
        .ok()?
        .split_whitespace()
        .next()?
        .parse()
        .ok()
}

/// Number of blocks and the x-range of a model JSON.
fn model_size(path: &Path) -> Result<(usize, u8, f64, f64), Fail> {
    let text =
        std::fs::read_to_string(path).map_err(|e| Fail(format!("{}: {e}", path.display())))?;
    let v: Value =
        serde_json::from_str(&text).map_err(|e| Fail(format!("{}: {e}", path.display())))?;
    let blocks = v["blocks"].as_array().map_or(&[][..], |b| b.as_slice());
    let mut dim = 2;
    let (mut lo, mut hi) = (f64::INFINITY, f64::NEG_INFINITY);
    for b in blocks {
        let pts = if let Some(p) = b["polygon"].as_array() {
            p
        } else {
            dim = 3;
            b["vertices"].as_array().map_or(&[][..], |p| p.as_slice())
        };
        for p in pts {
            if let Some(x) = p[0].as_f64() {
                lo = lo.min(x);
                hi = hi.max(x);
            }
        }
    }
    Ok((blocks.len(), dim, lo, hi))
}

/// The certificate, method and key number of a command's JSON result.
fn read_result(analysis: &str, v: &Value, cell: &mut Cell) {
    // tilt nests the limit result.
    let r = if analysis == "tilt" { &v["limit"] } else { v };
    let solver = if r["solver"].is_object() {
        &r["solver"]
    } else {
        &v["solver"]
    };
    cell.method = solver["method"].as_str().map(str::to_string);
    cell.tried = solver["tried"]
        .as_array()
        .map(|t| {
            t.iter()
                .filter_map(|x| x.as_str().map(str::to_string))
                .collect()
        })
        .unwrap_or_default();
    let c = &r["certificate"];
    if c.is_object() {
        cell.gap = c["gap"].as_f64().or(c["relative_gap"].as_f64());
        cell.admissibility = c["admissibility"].as_f64();
        cell.certified = c["ok"].as_bool();
    } else if r["no_equilibrium"].is_object() {
        // "Cannot stand": certified by the elastic program's Farkas certificate.
        cell.certified = r["no_equilibrium"]["ok"].as_bool();
    }
    cell.programs = program_lines(r);
    if !cell.programs.is_empty() && cell.certified.is_none() {
        cell.certified = Some(answered_certified(&cell.programs));
    }
    let num = |x: &Value| x.as_f64().map(|f| format!("{f:.6}"));
    cell.value = match analysis {
        "limit" => r["load_multiplier"].as_f64(),
        "settle" => r["work_dead_loads"].as_f64(),
        "capacity" => r["curve"]
            .as_array()
            .and_then(|c| c.last())
            .and_then(|p| p["load_multiplier"].as_f64()),
        "safety" => r["geometric_safety_factor"].as_f64(),
        "least-thickness" => r["thickness"].as_f64(),
        "tilt" => v["tilt_angle"].as_f64(),
        _ => None,
    };
    cell.result = match analysis {
        "limit" => num(&r["load_multiplier"])
            .map(|l| format!("λ = {l}"))
            .unwrap_or_else(|| r["message"].as_str().unwrap_or("").to_string()),
        "settle" => match num(&r["work_dead_loads"]) {
            Some(w) => format!("work {w} kN·m"),
            None => r["message"].as_str().unwrap_or("").to_string(),
        },
        "capacity" => {
            let curve = r["curve"].as_array().map_or(&[][..], |c| c.as_slice());
            let valid = curve.iter().filter(|p| p["valid"] == true).count();
            let last = curve.last().and_then(|p| num(&p["load_multiplier"]));
            format!(
                "{} steps ({valid} valid), λ {} → {}",
                curve.len(),
                curve
                    .first()
                    .and_then(|p| num(&p["load_multiplier"]))
                    .unwrap_or("—".into()),
                last.unwrap_or("—".into())
            )
        }
        "safety" => {
            let f = num(&r["geometric_safety_factor"]).unwrap_or(
                if r["stands"] == true {
                    "unbounded"
                } else {
                    "—"
                }
                .into(),
            );
            let ranges = r["reactions"].as_array().map_or(0, |a| a.len());
            format!(
                "{}; factor {f}; {ranges} supports' reaction ranges; {} LPs",
                if r["stands"] == true {
                    "stands"
                } else {
                    "does not stand"
                },
                r["solves"]
            )
        }
        "least-thickness" => format!(
            "t = {} m ({} steps)",
            num(&r["thickness"]).unwrap_or("—".into()),
            r["steps"]
        ),
        // No angle: the nested limit analysis says why (e.g. no equilibrium under the dead loads).
        "tilt" => num(&v["tilt_angle"])
            .map(|a| format!("{a} °"))
            .unwrap_or_else(|| format!("no angle: {}", r["message"].as_str().unwrap_or("—"))),
        _ => String::new(),
    };
}

fn na(m: &ModelDef, dim: u8, blocks: usize, analysis: &str, why: &str) -> Cell {
    Cell {
        model: m.name.clone(),
        dim,
        blocks,
        analysis: analysis.into(),
        outcome: "n/a".into(),
        command: String::new(),
        wall_s: None,
        cpu_s: None,
        peak_mib: None,
        load: None,
        method: None,
        tried: vec![],
        gap: None,
        admissibility: None,
        certified: None,
        programs: vec![],
        value: None,
        result: why.into(),
    }
}

/// Markdown header of the cell table.
pub fn header() -> String {
    "| model | dim | blocks | analysis | wall (s) | CPU (s) | peak MiB | load | method (fallbacks) | gap | admissibility | certified | result |\n|---|---:|---:|---|---:|---:|---:|---:|---|---:|---:|---|---|\n".into()
}

/// One markdown row.
pub fn row(c: &Cell) -> String {
    let f = |x: Option<f64>, p: usize| x.map_or("—".into(), |v| format!("{v:.p$}"));
    let e = |x: Option<f64>| x.map_or("—".into(), |v| format!("{v:.1e}"));
    let method = match &c.method {
        None => "—".to_string(),
        Some(m) if c.tried.is_empty() => m.clone(),
        Some(m) => format!(
            "{m} (after {})",
            c.tried
                .iter()
                .map(|t| t.split(':').next().unwrap_or(t))
                .collect::<Vec<_>>()
                .join(", ")
        ),
    };
    // Kinds of program answered by another method than the one reported (e.g. safety's
    // reaction ranges by primal simplex, warm-started): named after it, once per kind and method.
    let mut others: Vec<String> = vec![];
    for l in &c.programs {
        let s = format!("{}: {}", l.programs, l.method);
        if Some(&l.method) != c.method.as_ref() && !others.contains(&s) {
            others.push(s);
        }
    }
    let method = if others.is_empty() {
        method
    } else {
        format!("{method}; {}", others.join("; "))
    };
    let certified = match (c.outcome.as_str(), c.certified) {
        ("ok", Some(true)) => "yes".to_string(),
        ("ok", Some(false)) => "**no**".to_string(),
        ("ok", None) => "— (none reported)".to_string(),
        (o, _) => o.to_string(),
    };
    let result = match c.outcome.as_str() {
        "ok" | "n/a" => c.result.clone(),
        o => format!("**{o}**: {}", c.result),
    };
    format!(
        "| {} | {}D | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} |\n",
        c.model,
        c.dim,
        c.blocks,
        c.analysis,
        f(c.wall_s, 2),
        f(c.cpu_s, 2),
        f(c.peak_mib, 0),
        f(c.load, 1),
        method,
        e(c.gap),
        e(c.admissibility),
        certified,
        result.replace('|', "/")
    )
}

/// Run the benchmark: print the table row by row, write the JSON of every cell.
pub fn run(cfg: &Config) -> Result<Vec<Cell>, Fail> {
    let all = models();
    if let Some(names) = &cfg.models {
        for n in names {
            if !all.iter().any(|m| &m.name == n) {
                return Err(Fail(format!(
                    "--models {n}: no such model (one of {})",
                    all.iter()
                        .map(|m| m.name.as_str())
                        .collect::<Vec<_>>()
                        .join(", ")
                )));
            }
        }
    }
    if let Some(an) = &cfg.analyses {
        for a in an {
            if !ANALYSES.contains(&a.as_str()) {
                return Err(Fail(format!(
                    "--analyses {a}: no such analysis (one of {})",
                    ANALYSES.join(", ")
                )));
            }
        }
    }
    if !(cfg.cell_time_limit.is_finite() && cfg.cell_time_limit > 0.0) {
        return Err(Fail(format!(
            "--cell-time-limit {}: must be a finite number of seconds > 0",
            cfg.cell_time_limit
        )));
    }
    let chosen: Vec<ModelDef> = all
        .into_iter()
        .filter(|m| cfg.models.as_ref().is_none_or(|n| n.contains(&m.name)))
        .collect();
    let analyses: Vec<&str> = ANALYSES
        .iter()
        .copied()
        .filter(|a| {
            cfg.analyses
                .as_ref()
                .is_none_or(|n| n.iter().any(|x| x == a))
        })
        .collect();
    let lact3 = if chosen.iter().any(|m| matches!(m.source, Source::Dxf(_))) {
        Some(lact3_dir(&cfg.lact3)?)
    } else {
        None
    };
    let exe = std::env::current_exe().map_err(|e| Fail(format!("this binary's path: {e}")))?;
    let scratch = match &cfg.workdir {
        Some(d) => d.clone(),
        None => {
            std::env::temp_dir().join(format!("voussoir-bench-realistic-{}", std::process::id()))
        }
    };
    std::fs::create_dir_all(&scratch).map_err(|e| Fail(format!("{}: {e}", scratch.display())))?;
    println!(
        "Realistic models (issue 29 item 6): each cell is the command a user runs (its defaults{}), in a child process; wall and CPU seconds, the child's peak resident memory, the machine's 1-minute load average at the cell's start; cell time limit {} s{}. Scratch directory {}.\n",
        cfg.method
            .as_ref()
            .map_or(String::new(), |m| format!(", --method {m}")),
        cfg.cell_time_limit,
        if cfg.limit_cpu { " of CPU" } else { " (wall clock)" },
        scratch.display()
    );
    for m in &chosen {
        println!("- `{}`: {}", m.name, m.description);
    }
    println!();
    print!("{}", header());
    let mut cells = Vec::new();
    for mut m in chosen {
        let dir = scratch.join(&m.name);
        std::fs::create_dir_all(&dir).map_err(|e| Fail(format!("{}: {e}", dir.display())))?;
        // The two variants of the model: with live loads (limit, capacity) and without.
        let make = |variant: &str, extra: &[String]| -> Result<(), Fail> {
            let file = format!("{variant}.json");
            let args: Vec<String> = match &m.source {
                Source::Gen { args, .. } => {
                    let mut a = vec!["gen".to_string()];
                    a.extend(args.iter().cloned());
                    a.extend(extra.iter().cloned());
                    a.extend(["-o".to_string(), file.clone()]);
                    a
                }
                Source::Dxf(f) => {
                    let path = lact3.as_ref().expect("lact3 folder").join(f);
                    if !path.is_file() {
                        return Err(Fail(format!(
                            "{}: missing LACT3 drawing (crates/voussoir-io/tests/fixtures/lact3/README.md)",
                            path.display()
                        )));
                    }
                    let mut a = vec![
                        "import".to_string(),
                        path.display().to_string(),
                        "--units".into(),
                        "mm".into(),
                    ];
                    a.extend(extra.iter().cloned());
                    a.extend(["-o".to_string(), file.clone()]);
                    a
                }
            };
            let r = run_child(&exe, &args, &dir, 600.0, false, None)?;
            if r.status != Some(0) {
                return Err(Fail(format!(
                    "{}: making the model failed: {}",
                    m.name,
                    r.stderr.trim()
                )));
            }
            Ok(())
        };
        let (live, dead) = match &m.source {
            Source::Gen { live, dead, .. } => (live.clone(), dead.clone()),
            Source::Dxf(_) => (s(&["--live", "horizontal"]), s(&["--live", "none"])),
        };
        make("live", &live)?;
        make("dead", &dead)?;
        let (blocks, dim, x0, x1) = model_size(&dir.join("dead.json"))?;
        if matches!(m.source, Source::Dxf(_)) {
            let mid = 0.5 * (x0 + x1);
            m.motion = Ok(vec![
                "--split".into(),
                format!("base@{mid}"),
                "--move".into(),
                "base@1=0,-0.01".into(),
            ]);
        }
        if cfg.max_blocks.is_some_and(|n| blocks > n) {
            for a in &analyses {
                let c = na(&m, dim, blocks, a, "skipped: above --max-blocks");
                print!("{}", row(&c));
                cells.push(c);
            }
            continue;
        }
        for &a in &analyses {
            let mut args: Vec<String> = vec![a.to_string()];
            match a {
                "limit" => args.push("live.json".into()),
                "capacity" => {
                    args.push("live.json".into());
                    args.extend(s(&["--steps", "20"]));
                }
                "least-thickness" => match &m.least_thickness {
                    Some(lt) => args.extend(lt.iter().cloned()),
                    None => {
                        let c = na(&m, dim, blocks, a, "not a generated arch or dome");
                        print!("{}", row(&c));
                        cells.push(c);
                        continue;
                    }
                },
                _ => args.push("dead.json".into()),
            }
            if matches!(a, "settle" | "capacity") {
                match &m.motion {
                    Ok(mv) => args.extend(mv.iter().cloned()),
                    Err(why) => {
                        let c = na(&m, dim, blocks, a, why);
                        print!("{}", row(&c));
                        cells.push(c);
                        continue;
                    }
                }
            }
            // `safety` and `tilt` take --friction but refuse --non-associative (associative
            // friction only): they run the model's μ associatively and the result says so,
            // rather than a cell that fails on the flag.
            let associative_only =
                matches!(a, "safety" | "tilt") && m.flags.iter().any(|f| f == "--non-associative");
            if a != "least-thickness" {
                args.extend(
                    m.flags
                        .iter()
                        .filter(|f| !(associative_only && *f == "--non-associative"))
                        .cloned(),
                );
            }
            if let Some(method) = &cfg.method {
                args.extend(["--method".to_string(), method.clone()]);
            }
            // The result as JSON on stdout (the same as `-o`'s, which for least-thickness is
            // the model at the least thickness).
            let out = format!("{a}.out.json");
            args.push("--json".to_string());
            let mut cell = na(&m, dim, blocks, a, "");
            cell.command = format!("voussoir {}", args.join(" "));
            cell.load = load_average();
            let r = run_child(
                &exe,
                &args,
                &dir,
                cfg.cell_time_limit,
                cfg.limit_cpu,
                Some(&dir.join(&out)),
            )?;
            cell.wall_s = Some(r.wall);
            cell.cpu_s = Some(r.cpu);
            cell.peak_mib = Some(r.peak_mib);
            if r.timed_out {
                cell.outcome = "timed out".into();
                cell.result = format!(
                    "timed out after {} s{}",
                    cfg.cell_time_limit,
                    if cfg.limit_cpu { " of CPU" } else { "" }
                );
            } else if r.status != Some(0) {
                cell.outcome = "failed".into();
                cell.result = r
                    .stderr
                    .lines()
                    .rev()
                    .find(|l| l.starts_with("error"))
                    .unwrap_or(r.stderr.trim())
                    .to_string();
            } else {
                let parsed = std::fs::read_to_string(dir.join(&out))
                    .ok()
                    .and_then(|t| serde_json::from_str::<Value>(&t).ok());
                match parsed {
                    Some(v) => {
                        cell.outcome = "ok".into();
                        read_result(a, &v, &mut cell);
                        if associative_only {
                            cell.result = format!(
                                "associative μ (`{a}` has no --non-associative): {}",
                                cell.result
                            );
                        }
                    }
                    None => {
                        cell.outcome = "failed".into();
                        cell.result = "no JSON result written".into();
                    }
                }
            }
            print!("{}", row(&cell));
            cells.push(cell);
        }
    }
    if let Some(path) = &cfg.output {
        let json =
            serde_json::to_string_pretty(&cells).map_err(|e| Fail(format!("--output: {e}")))?;
        crate::outputs::stage(path, json.as_bytes())?;
        crate::outputs::commit()?;
    }
    let mut summary = String::new();
    let ran: Vec<&Cell> = cells.iter().filter(|c| c.outcome != "n/a").collect();
    let _ = writeln!(
        summary,
        "\n{} cells run: {} ok ({} certified, {} not certified, {} without a certificate), {} failed, {} timed out.",
        ran.len(),
        ran.iter().filter(|c| c.outcome == "ok").count(),
        ran.iter().filter(|c| c.outcome == "ok" && c.certified == Some(true)).count(),
        ran.iter().filter(|c| c.outcome == "ok" && c.certified == Some(false)).count(),
        ran.iter().filter(|c| c.outcome == "ok" && c.certified.is_none()).count(),
        ran.iter().filter(|c| c.outcome == "failed").count(),
        ran.iter().filter(|c| c.outcome == "timed out").count(),
    );
    print!("{summary}");
    Ok(cells)
}
