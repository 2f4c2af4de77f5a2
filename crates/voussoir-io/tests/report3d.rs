//! The interactive 3D report (report3d.rs): deterministic bytes, nothing fetched from the
//! network, and embedded data that parses back to the result's blocks, joints and motions.
//! The browser side (WebGL drawn, drag rotates, no console errors) is checked by
//! scripts/check-report3d.sh in headless Chromium.

use voussoir::analysis::limit::{limit, LimitStatus};
use voussoir::analysis::SettlementResult;
use voussoir::dim::Three;
use voussoir::lp::SolverOptions;
use voussoir::model3d::AnyModel;
use voussoir::{BuildOptions, Structure3d};
use voussoir_io::report3d::report3d_html;

fn vault_limit() -> voussoir::analysis::LimitResult<Three> {
    let text = include_str!("fixtures/vault3d.json");
    let AnyModel::Spatial(m) = AnyModel::from_json(text).unwrap() else {
        panic!("the vault fixture is 3D")
    };
    let st = Structure3d::new(&m, BuildOptions::default()).unwrap();
    let r = limit(&st, &SolverOptions::default()).unwrap();
    assert_eq!(r.status, LimitStatus::Collapse);
    r
}

/// The JSON inside `<script type="application/json" id="voussoir-data">`.
fn data(html: &str) -> serde_json::Value {
    let open = "<script type=\"application/json\" id=\"voussoir-data\">";
    let i = html.find(open).expect("data script") + open.len();
    let j = i + html[i..].find("</script>").expect("end of the data script");
    serde_json::from_str(&html[i..j].replace("<\\/", "</")).expect("the data parses")
}

fn no_network(html: &str) {
    for bad in [
        "<script src",
        "<link",
        "@import",
        "fetch(",
        "XMLHttpRequest",
        "<iframe",
        "<img",
        "src=",
    ] {
        assert!(!html.contains(bad), "the report contains {bad}");
    }
    // `url(` only for the SVG's own patterns (`url(#id)`).
    for (k, _) in html.match_indices("url(") {
        assert!(
            html[k..].starts_with("url(#"),
            "{}",
            &html[k..(k + 40).min(html.len())]
        );
    }
    // The only addresses are XML namespaces of the inline SVG, which are names, not fetches.
    for (k, _) in html.match_indices("http") {
        let tail = &html[k..(k + 40).min(html.len())];
        assert!(
            tail.starts_with("http://www.w3.org/2000/svg")
                || tail.starts_with("http://www.w3.org/1999/xlink"),
            "network address in the report: {tail}"
        );
    }
}

#[test]
fn limit_report_is_deterministic_offline_and_carries_the_blocks() {
    let r = vault_limit();
    let a = report3d_html(&r, "Vault strip", "vault3d.json").unwrap();
    let b = report3d_html(&r, "Vault strip", "vault3d.json").unwrap();
    assert_eq!(a, b, "same result, same bytes");
    // A second analysis of the same model gives the same page too.
    let c = report3d_html(&vault_limit(), "Vault strip", "vault3d.json").unwrap();
    assert_eq!(a, c, "a second solve gives the same bytes");
    no_network(&a);
    assert!(a.starts_with("<!DOCTYPE html>") && a.ends_with("</html>\n"));
    assert!(a.contains("<canvas id=\"v3-canvas\"") && a.contains("__voussoirRotate"));
    assert!(a.contains("<svg"), "the static drawing is there for print");
    // λ in the key numbers, as printed with 6 significant digits.
    let l = r.load_multiplier.unwrap();
    let shown = voussoir_io::draw::svg::human(l, 6);
    assert!(
        a.contains(&format!(
            "<th>collapse load multiplier λ</th><td>{shown}</td>"
        )),
        "{shown}"
    );

    let d = data(&a);
    let blocks = d["blocks"].as_array().unwrap();
    assert_eq!(blocks.len(), r.geometry.blocks.len());
    assert_eq!(blocks.len(), 7);
    assert_eq!(d["supports"].as_array().unwrap().len(), 2);
    assert_eq!(d["joints"].as_array().unwrap().len(), r.joints.len());
    for (i, b) in blocks.iter().enumerate() {
        // Six quadrilateral faces, two triangles each.
        assert_eq!(b["f"].as_array().unwrap().len(), 6);
        assert_eq!(b["t"].as_array().unwrap().len(), 12);
        // The centroid and the motion are the result's (to the 9 significant digits written).
        let c = &r.geometry.centroids[i];
        for k in 0..3 {
            let x = b["c"][k].as_f64().unwrap();
            assert!(
                (x - c[k]).abs() <= 1e-8 * (1.0 + c[k].abs()),
                "block {i}: {x} vs {}",
                c[k]
            );
        }
        if let Some(m) = r.blocks.iter().find(|m| m.id == i) {
            let u = b["m"][0].as_f64().unwrap();
            assert!((u - m.u).abs() <= 1e-8 * (1.0 + m.u.abs()));
        }
    }
    // Cracked joints are listed in the table, one row each.
    let cracked = r
        .joints
        .iter()
        .filter(|j| j.state != voussoir::result::JointState::Closed)
        .count();
    assert!(
        cracked >= 3,
        "a 3D arch mechanism opens at least three joints, found {cracked}"
    );
    let table =
        &a[a.find("<h2>Cracked joints</h2>").unwrap()..a.find("<h2>Static drawing</h2>").unwrap()];
    // The section has the cracks as the summary lists them (one row per crack of the result's
    // `cracks`), then the cracked joints (one row per joint that is not closed).
    assert!(!r.cracks.is_empty());
    assert_eq!(table.matches("<tr><td>").count(), r.cracks.len() + cracked);
    for (i, c) in r.cracks.iter().enumerate() {
        let row = format!("<tr><td>{}</td><td>", i + 1);
        assert!(table.contains(&row), "crack {} has no row", i + 1);
        assert!(
            table.contains(&format!("joint {} (", c.joints[0])) || c.joints.len() > 1,
            "crack {} does not name its joint",
            i + 1
        );
    }
}

#[test]
fn settlement_report_shows_the_certificate() {
    let r: SettlementResult<Three> =
        serde_json::from_str(include_str!("fixtures/settlement3d_two_cubes.json")).unwrap();
    let html = report3d_html(&r, "", "settlement3d_two_cubes.json").unwrap();
    no_network(&html);
    assert!(html.contains("<title>Settlement mechanism</title>"));
    let c = r
        .certificate
        .as_ref()
        .expect("the fixture has a certificate");
    for (name, v) in [
        ("primal (work of the dead loads, kN·m)", c.primal),
        ("dual (work of the reactions, kN·m)", c.dual),
        ("relative duality gap", c.relative_gap),
    ] {
        let row = format!(
            "<th>{name}</th><td>{}</td>",
            voussoir_io::draw::svg::human(v, 6)
        );
        assert!(html.contains(&row), "missing {row}");
    }
    let d = data(&html);
    assert_eq!(
        d["blocks"].as_array().unwrap().len(),
        r.geometry.blocks.len()
    );
    assert_eq!(d["units"], "metres");
    assert_eq!(
        html,
        report3d_html(&r, "", "settlement3d_two_cubes.json").unwrap()
    );
}

#[test]
fn a_result_with_a_bad_face_is_refused_in_one_line() {
    let mut r = vault_limit();
    r.geometry.blocks[3].faces[0][0] = 99;
    let e = report3d_html(&r, "", "").unwrap_err().to_string();
    assert!(e.starts_with("block 3:") && !e.contains('\n'), "{e}");
}
