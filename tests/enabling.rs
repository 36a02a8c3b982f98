//! Which extensions the safe constructors enable: over every extension ash has,
//! emitting one never makes a method that is safe without it `unsafe`; each one
//! refused brings an unenforced rule to a method outside it.

mod common;

use common::root;
use std::collections::BTreeMap;
use tuff_gen::{config::Config, model::Model, plan, registry, Options};

/// Each method's safety, by command.
type Safety = BTreeMap<String, bool>;
/// Each refused extension with the VUIDs of the rules it would bring elsewhere.
type Refused = Vec<(String, Vec<String>)>;

/// Each method's safety, and the refused extensions with their rules, for `config`.
fn plan_for(config: &Config) -> (Safety, Refused) {
    let opts = Options::pinned();
    let reg = registry::load_registry(&opts.registry).expect("registry");
    let reference = registry::load_registry(&root().join("reference/vk.xml")).expect("reference");
    let vu = registry::load_validusage(opts.validusage.as_ref().expect("validusage"))
        .expect("validusage");
    let model = Model::build(&reg, Some(&reference), config, &opts.config).expect("model");
    let validity = tuff_gen::enabled_validity(&model, Some(&vu));
    let cx = plan::Context::new(&model, &validity);
    let plans = plan::Plans::build(&cx);
    let safety = plans
        .methods
        .iter()
        .map(|m| (m.command.clone(), plans.safety[&m.command].safe()))
        .collect();
    let refused = plans
        .enabling
        .refused
        .iter()
        .map(|(x, rules)| (x.clone(), rules.iter().map(|r| r.vuid.clone()).collect()))
        .collect();
    (safety, refused)
}

#[test]
fn enabling_every_extension_ash_has_makes_no_safe_method_unsafe() {
    let all = Config::load(&Options::pinned().config).expect("pinned config");
    assert!(
        all.all_extensions,
        "the pinned config emits every extension"
    );
    // The scenes' extensions alone: the baseline every safe method is measured from.
    let scenes = Config {
        all_extensions: false,
        ..all.clone()
    };
    let (few, refused_few) = plan_for(&scenes);
    let (many, refused) = plan_for(&all);
    assert!(refused_few.is_empty(), "{refused_few:?}");
    let lost: Vec<&String> = few
        .iter()
        .filter(|(m, safe)| **safe && many.get(*m) == Some(&false))
        .map(|(m, _)| m)
        .collect();
    assert!(
        lost.is_empty(),
        "safe with the scenes' extensions only: {lost:?}"
    );
    assert!(many.len() > 2 * few.len(), "{} methods", many.len());
    // Some are refused, each for rules it names. The recorder's typestate follows
    // the video coding scope, so its rules never refuse the video extension; the
    // video profile's own rules, which no check enforces, do.
    assert!(!refused.is_empty());
    assert!(refused.iter().all(|(_, rules)| !rules.is_empty()));
    assert!(
        refused
            .iter()
            .all(|(_, rules)| !rules.iter().any(|v| v.ends_with("-videocoding"))),
        "{refused:?}"
    );
    let video = refused
        .iter()
        .find(|(x, _)| x == "VK_KHR_video_queue")
        .expect("VK_KHR_video_queue is refused");
    assert!(
        video
            .1
            .iter()
            .any(|v| v.starts_with("VUID-VkVideoProfileInfoKHR-")),
        "{video:?}"
    );
    // Those the scenes need stay enabled.
    for x in ["VK_KHR_surface", "VK_KHR_swapchain", "VK_EXT_debug_utils"] {
        assert!(!refused.iter().any(|(r, _)| r == x), "{x} is refused");
    }
}
