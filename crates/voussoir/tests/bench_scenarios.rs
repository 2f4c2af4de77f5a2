//! `voussoir bench`'s 3D limit analyses with the exact friction cone (issue 18): the option
//! swaps the inscribed pyramid's rows for one second-order cone per point, and the collapse it
//! certifies is at least the pyramid's (the pyramid is inscribed in the cone, so every force
//! state it admits the cone admits too: the static λ cannot drop).

use voussoir::bench::{bench_run, Analysis, BenchConfig, BenchMethod, Scenario};
use voussoir::lp::Method;

fn lambda(outcome: &str) -> f64 {
    outcome
        .strip_prefix("λ = ")
        .and_then(|v| v.parse().ok())
        .unwrap_or_else(|| panic!("no collapse multiplier in {outcome:?}"))
}

#[test]
fn the_exact_cone_keeps_only_the_equilibrium_rows_and_never_lowers_the_collapse_load() {
    for (scenario, n) in [(Scenario::Dome, 50), (Scenario::Vault, 128)] {
        let run = |exact_cone| {
            let cfg = BenchConfig {
                method: BenchMethod::Fixed(Method::Clarabel),
                exact_cone,
                ..BenchConfig::default()
            };
            bench_run(scenario, Analysis::Limit, n, &cfg)
                .unwrap()
                .expect("a limit analysis")
        };
        let (pyramid, cone) = (run(false), run(true));
        let name = scenario.name();
        assert_eq!(pyramid.units, cone.units, "{name}");
        // Six equilibrium rows per block (three forces, three moments) and nothing else: the
        // friction is in the cones. The pyramid adds its facet rows.
        assert_eq!(cone.rows, 6 * cone.units, "{name}");
        assert!(pyramid.rows > cone.rows, "{name}: {}", pyramid.rows);
        for r in [&pyramid, &cone] {
            assert!(r.gap <= 1e-6 && r.violation <= 1e-6, "{name}: {r:?}");
        }
        let (lp, lc) = (lambda(&pyramid.outcome), lambda(&cone.outcome));
        assert!(
            lc >= lp * (1.0 - 1e-6),
            "{name}: cone λ {lc} below pyramid λ {lp}"
        );
        eprintln!("{name}: {} blocks, pyramid λ {lp}, cone λ {lc}", cone.units);
    }
}
