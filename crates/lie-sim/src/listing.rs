//! `lie-sim methods`: the method registry as a listing — every method with what it is, the options
//! it takes and the systems it applies to, and what each configuration `trade` runs is, as the
//! library describes it (`integrators::MethodInfo` of the built method) — in plain text or as the
//! Markdown tables of the docs (`lie-sim methods --markdown`).
//!
//! Nothing here is written per method or per system: the rows come from [`crate::methods`], the
//! systems from [`crate::systems`] (each probed on its example scene), the descriptors from the
//! methods built on those scenes.

use crate::build::{build, probe};
use crate::error::SimError;
use crate::methods::row::{Stepping, TauRule};
use crate::methods::wrap::BuildError;
use crate::methods::{candidates, MethodId, MethodSpec};
use crate::scene::{Overrides, Scene};
use crate::systems::SystemKind;
use crate::taus::TauKind;
use std::fmt::Write as _;

/// The options a method takes, as a phrase: `τ (exp or cayley), θ, composition, processing`
/// (no `|`: the phrase is also a Markdown table cell).
pub fn takes(m: MethodId) -> String {
    let t = m.row().takes;
    let taus: Vec<&str> = TauKind::ALL.iter().map(|t| t.name()).collect();
    let mut v: Vec<String> = Vec::new();
    match t.tau {
        TauRule::None => {}
        TauRule::Any => v.push(format!("τ ({})", taus.join(" or "))),
        TauRule::Only(only) => v.push(format!("τ = {only} only")),
    }
    if t.theta {
        v.push("θ".into());
    }
    if t.coefficients {
        v.push("splitting (coefficients)".into());
    }
    if t.modified {
        v.push("modified, order".into());
    }
    if t.wrappers {
        v.push("composition, processing (symmetric base)".into());
        // The methods `wrap` builds: a symmetric configuration keeps its system as the monitor
        // of reversible variable steps.
        v.push("epsilon instead of step (symmetric configurations)".into());
    }
    if t.stepping == Stepping::Tolerance {
        v.push("tolerance (or rtol and atol) instead of step".into());
    }
    if v.is_empty() {
        "—".into()
    } else {
        v.join(", ")
    }
}

/// Every system's example scene.
fn examples() -> Result<Vec<Scene>, SimError> {
    SystemKind::ALL
        .iter()
        .map(|k| {
            Scene::parse(
                k.example(),
                &format!("{k} example"),
                k.name(),
                Overrides::default(),
            )
        })
        .collect()
}

/// A method's representative configuration: its first candidate.
fn representative(m: MethodId) -> MethodSpec {
    candidates()
        .into_iter()
        .find(|s| s.method == m)
        .unwrap_or_else(|| MethodSpec::plain(m))
}

/// Whether `m` applies to `scene`'s system, or why not.
fn applies(m: MethodId, scene: &Scene) -> Result<Result<(), String>, SimError> {
    let spec = representative(m);
    let probed = probe(&scene.system, &spec, scene.reconstruct, &scene.solver)?;
    Ok(match probed.built {
        Ok(()) => Ok(()),
        Err(BuildError::Integrator(e)) => Err(e.to_string()),
        Err(e) => Err(e.to_string()),
    })
}

/// What `spec` is on `scene`'s system, as the library reports it, or `—` where it does not
/// apply.
fn info(spec: &MethodSpec, scene: &Scene) -> String {
    match build(&scene.system, spec, scene.reconstruct, &scene.solver) {
        Ok(sim) => sim.info().to_string(),
        Err(_) => "—".into(),
    }
}

/// The listing: plain text, or the docs' Markdown tables.
pub fn listing(markdown: bool) -> Result<String, SimError> {
    let scenes = examples()?;
    let mut s = String::new();
    if markdown {
        let _ = writeln!(s, "| method | what it is | takes | applies to |");
        let _ = writeln!(s, "|---|---|---|---|");
    }
    for &m in MethodId::ALL {
        let mut yes = Vec::new();
        let mut no = Vec::new();
        for scene in &scenes {
            match applies(m, scene)? {
                Ok(()) => yes.push(scene.system.kind().name()),
                Err(why) => no.push((scene.system.kind().name(), why)),
            }
        }
        if markdown {
            let _ = writeln!(
                s,
                "| `{m}` | {} | {} | {} |",
                m.row().summary,
                takes(m),
                yes.join(", ")
            );
        } else {
            let _ = writeln!(s, "{m}\n  {}\n  takes: {}", m.row().summary, takes(m));
            let _ = writeln!(s, "  applies to: {}", yes.join(", "));
            for (kind, why) in no {
                let _ = writeln!(s, "  not {kind}: {why}");
            }
        }
    }
    if markdown {
        let heads: Vec<&Scene> = scenes
            .iter()
            .filter(|sc| {
                matches!(
                    sc.system.kind(),
                    SystemKind::FreeRigidBody | SystemKind::HeavyTop
                )
            })
            .collect();
        let _ = writeln!(
            s,
            "\nWhat each configuration `trade` runs is, as the integrators crate reports it \
             (`MethodInfo`), on the example scenes:\n"
        );
        let names: Vec<String> = heads
            .iter()
            .map(|sc| sc.system.kind().to_string())
            .collect();
        let _ = writeln!(s, "| configuration | {} |", names.join(" | "));
        let _ = writeln!(s, "|---|{}", "---|".repeat(heads.len()));
        for spec in candidates() {
            let cells: Vec<String> = heads.iter().map(|sc| info(&spec, sc)).collect();
            let _ = writeln!(s, "| `{spec}` | {} |", cells.join(" | "));
        }
        let _ = writeln!(s, "\n| system | what it is | `[forces]` |");
        let _ = writeln!(s, "|---|---|---|");
        for &k in SystemKind::ALL {
            let names: Vec<String> = std::iter::once(k.name())
                .chain(k.aliases().iter().copied())
                .map(|n| format!("`{n}`"))
                .collect();
            let forces = if k.force_keys().is_empty() {
                "—".to_string()
            } else {
                k.force_keys().join(", ")
            };
            let _ = writeln!(s, "| {} | {} | {forces} |", names.join(" = "), k.summary());
        }
    } else {
        let _ = writeln!(s, "\nsystems:");
        for &k in SystemKind::ALL {
            let _ = writeln!(s, "  {:<20} {}", k.name(), k.summary());
        }
    }
    Ok(s)
}

/// The short list for `--help`: each method and the options it takes.
pub fn help() -> String {
    let mut s = String::from("Methods (lie-sim methods lists where each applies):\n");
    for &m in MethodId::ALL {
        let _ = writeln!(s, "  {:<16} takes {}", m.name(), takes(m));
    }
    s.push_str("Systems: ");
    let kinds: Vec<&str> = SystemKind::ALL.iter().map(|k| k.name()).collect();
    s.push_str(&kinds.join(", "));
    s
}
