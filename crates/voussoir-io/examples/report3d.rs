//! Write the interactive 3D report of a 3D model (until the CLI's `--report` takes 3D models):
//!
//!     cargo run --release -p voussoir-io --example report3d -- MODEL.json OUT.html [SUPPORT=u,v,w]
//!
//! Without a support motion: limit analysis of the model's live loads. With `SUPPORT=u,v,w`
//! (metres): settlement analysis for that support translation. Used by scripts/check-report3d.sh.

use std::process::ExitCode;
use voussoir::analysis::limit::limit;
use voussoir::analysis::settlement::settle;
use voussoir::lp::SolverOptions;
use voussoir::model3d::AnyModel;
use voussoir::{BuildOptions, Structure3d};
use voussoir_io::report3d::report3d_html;

fn run() -> Result<(), String> {
    let args: Vec<String> = std::env::args().skip(1).collect();
    if args.len() < 2 || args.len() > 3 {
        return Err("usage: report3d MODEL.json OUT.html [SUPPORT=u,v,w]".into());
    }
    let model = match voussoir_io::read_any_model(args[0].as_ref()).map_err(|e| e.0)? {
        AnyModel::Spatial(m) => m,
        AnyModel::Planar(_) => return Err(format!("{} is a 2D model", args[0])),
    };
    let mut model = model;
    let html = if let Some(mv) = args.get(2) {
        let (name, uvw) = mv
            .split_once('=')
            .ok_or_else(|| format!("{mv}: expected SUPPORT=u,v,w"))?;
        let v: Vec<f64> = uvw
            .split(',')
            .map(|t| t.trim().parse::<f64>())
            .collect::<Result<_, _>>()
            .map_err(|e| format!("{mv}: {e}"))?;
        if v.len() != 3 {
            return Err(format!("{mv}: expected three numbers u,v,w"));
        }
        let k = model
            .support_index(name)
            .ok_or_else(|| format!("no support named '{name}'"))?;
        model.supports[k].motion = [v[0], v[1], v[2], 0.0, 0.0, 0.0];
        let st = Structure3d::new(&model, BuildOptions::default()).map_err(|e| e.to_string())?;
        let r = settle(&st, &SolverOptions::default()).map_err(|e| e.to_string())?;
        report3d_html(&r, "", &args[0]).map_err(|e| e.0)?
    } else {
        let st = Structure3d::new(&model, BuildOptions::default()).map_err(|e| e.to_string())?;
        let r = limit(&st, &SolverOptions::default()).map_err(|e| e.to_string())?;
        report3d_html(&r, "", &args[0]).map_err(|e| e.0)?
    };
    voussoir_io::write_atomic(args[1].as_ref(), html.as_bytes()).map_err(|e| e.0)?;
    eprintln!("wrote {} ({} bytes)", args[1], html.len());
    Ok(())
}

fn main() -> ExitCode {
    match run() {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("error: {e}");
            ExitCode::FAILURE
        }
    }
}
