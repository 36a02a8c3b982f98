//! The registry pass, the implicit-rule derivation and the report's totals, on the
//! pinned 1.3.239 registry and on the newer 1.4.309; the derivation also against the
//! toolchain's lists of 1.3.281 and 1.4.330.

mod common;

use common::{load, root, shared_registry, Loaded};
use std::collections::{BTreeMap, BTreeSet};
use std::sync::OnceLock;
use tuff_gen::registry;
use tuff_gen::validity::Category;

fn pinned() -> &'static Loaded {
    static L: OnceLock<Loaded> = OnceLock::new();
    L.get_or_init(|| load(&root(), false))
}

fn newer() -> &'static Loaded {
    static L: OnceLock<Loaded> = OnceLock::new();
    L.get_or_init(|| load(&shared_registry("1.4.309"), false))
}

#[test]
fn pinned_vk_xml_and_validusage_json_are_the_same_version() {
    let reg = registry::load_registry(&root().join("vk.xml")).unwrap();
    let vu = registry::load_validusage(&root().join("validusage.json")).unwrap();
    assert_eq!(reg.version, "1.3.239");
    assert_eq!(vu.api_version, reg.version);
}

#[derive(serde::Deserialize)]
struct Exceptions {
    exception: Vec<Exception>,
}

#[derive(serde::Deserialize)]
struct Exception {
    registry: String,
    vuid: String,
    side: String,
    reason: String,
}

fn check_agreement(l: &Loaded, version: &str) {
    let c = l
        .validity
        .comparison
        .as_ref()
        .expect("validusage.json was given");
    println!(
        "{version}: derived {}, listed {}, both {}, only derived {}, only listed {}",
        c.derived,
        c.listed,
        c.both,
        c.only_derived.len(),
        c.only_listed.len()
    );
    println!("  only derived: {:?}", c.only_derived);
    println!("  only listed: {:?}", c.only_listed);
    assert!(
        c.recall() >= 0.999,
        "listed rules derived: {:.4}",
        c.recall()
    );
    assert!(
        c.precision() >= 0.999,
        "derived rules listed: {:.4}",
        c.precision()
    );

    let text =
        std::fs::read_to_string(root().join("generator/derivation-exceptions.toml")).unwrap();
    let file: Exceptions = toml::from_str(&text).unwrap();
    let mut expected: BTreeMap<(&str, &str), ()> = BTreeMap::new();
    for e in file.exception.iter().filter(|e| e.registry == version) {
        assert!(!e.reason.trim().is_empty(), "{} has no reason", e.vuid);
        expected.insert((e.side.as_str(), e.vuid.as_str()), ());
    }
    let mut actual: BTreeMap<(&str, &str), ()> = BTreeMap::new();
    for v in &c.only_listed {
        actual.insert(("listed", v), ());
    }
    for v in &c.only_derived {
        actual.insert(("derived", v), ());
    }
    assert_eq!(
        actual.keys().collect::<Vec<_>>(),
        expected.keys().collect::<Vec<_>>(),
        "the differences must be exactly the checked-in exceptions of {version}"
    );
}

#[test]
fn derivation_agrees_with_validusage_1_3_239() {
    check_agreement(pinned(), "1.3.239");
}

#[test]
fn derivation_agrees_with_validusage_1_4_309() {
    check_agreement(newer(), "1.4.309");
}

#[test]
fn derivation_covers_every_item_of_the_registry() {
    // The specification's generator writes implicit rules for more items than
    // validusage.json lists (alias commands among them).
    let total = |l: &Loaded| l.validity.rules.iter().filter(|r| r.derived).count();
    assert_eq!(total(pinned()), 5040);
    assert_eq!(total(newer()), 6029);
}

fn category_counts(l: &Loaded) -> [usize; 3] {
    let mut n = [0; 3];
    for r in l.validity.rules.iter().filter(|r| r.listed) {
        n[Category::ALL.iter().position(|c| *c == r.category).unwrap()] += 1;
    }
    n
}

#[test]
fn every_listed_vuid_is_counted_once_in_one_category() {
    for (l, listed_total) in [(pinned(), 14_942), (newer(), 20_111)] {
        let vu = l.validusage.as_ref().unwrap();
        let distinct: BTreeSet<&str> = vu.entries.iter().map(|e| e.vuid.as_str()).collect();
        assert_eq!(vu.entries.len(), listed_total);
        assert_eq!(distinct.len(), vu.entries.len(), "VUIDs are distinct");
        let listed: Vec<&str> = l
            .validity
            .rules
            .iter()
            .filter(|r| r.listed)
            .map(|r| r.vuid.as_str())
            .collect();
        assert_eq!(listed.len(), listed_total);
        assert_eq!(category_counts(l).iter().sum::<usize>(), listed_total);
    }
    assert_eq!(category_counts(pinned()), [4676, 1768, 8498]);
}

#[test]
fn the_malformed_vuid_of_1_3_239_is_explicit() {
    let rule = pinned()
        .validity
        .rules
        .iter()
        .find(|r| r.vuid == "VUID-VkInstanceCreateInfo-pNext")
        .expect("listed");
    assert_eq!(rule.category, Category::Creation);
}

#[test]
fn conditions_come_from_vk_xml() {
    let m = &pinned().model;
    assert_eq!(m.condition("vkCmdDraw").text(), "core");
    // A promoted command exists with its version or with the extension whose alias
    // names it.
    assert_eq!(
        m.condition("vkCmdBeginRendering").text(),
        "VK_KHR_dynamic_rendering,VK_VERSION_1_3"
    );
    assert_eq!(
        m.condition("vkCreateSwapchainKHR").text(),
        "VK_KHR_swapchain"
    );
    assert!(m.emitted.contains("vkCreateSwapchainKHR"));
    assert!(m.emitted.contains("vkCmdBeginRendering"));
    // Every extension is emitted (no reference registry here leaves one out).
    assert!(m.emitted.contains("vkCmdDrawMeshTasksEXT"));
    // Same answer on the newer registry, whose validusage.json files everything
    // under `core`.
    let n = &newer().model;
    assert_eq!(
        n.condition("vkCmdDrawMeshTasksEXT").text(),
        "VK_EXT_mesh_shader"
    );
    // A 1.4 command is emitted only with the extension it was promoted from.
    assert!(n.emitted.contains("vkCmdPushDescriptorSet"));
    assert_eq!(
        n.condition("vkCmdPushDescriptorSet").text(),
        "VK_KHR_push_descriptor,VK_VERSION_1_4"
    );
    let scenes = common::load_scenes(&shared_registry("1.4.309"));
    assert!(
        !scenes.model.emitted.contains("vkCmdPushDescriptorSet"),
        "1.4 is above the cap"
    );
}

#[test]
fn emitted_api_matches_the_cross_check() {
    // With the per-rule keys of 1.3.239's validusage.json, the API of core and the
    // scenes' eight extensions has about 2,057 implicit and 742 creation rules.
    let l = &common::load_scenes(&root());
    let count = |cat: Category, by_key: bool| {
        l.validity
            .rules
            .iter()
            .filter(|r| r.listed && r.emitted && r.category == cat)
            .filter(|r| !by_key || r.key_holds == Some(true))
            .count()
    };
    let near = |got: usize, want: usize| got.abs_diff(want) * 100 <= want;
    assert!(
        near(count(Category::Implicit, false), 2057),
        "{}",
        count(Category::Implicit, false)
    );
    assert!(near(count(Category::Implicit, true), 2057));
    assert!(
        near(count(Category::Creation, true), 742),
        "{}",
        count(Category::Creation, true)
    );
}

#[test]
fn handles_know_their_parents_and_lifetime_commands() {
    let h = &pinned().model.handles;
    let buffer = &h["VkBuffer"];
    assert!(!buffer.dispatchable);
    assert_eq!(
        buffer.parent_chain,
        ["VkDevice", "VkPhysicalDevice", "VkInstance"]
    );
    assert_eq!(buffer.created_by, ["vkCreateBuffer"]);
    assert_eq!(buffer.destroyed_by, ["vkDestroyBuffer"]);
    let cb = &h["VkCommandBuffer"];
    assert!(cb.dispatchable);
    assert_eq!(cb.parent_chain[0], "VkCommandPool");
    assert_eq!(cb.created_by, ["vkAllocateCommandBuffers"]);
    assert_eq!(cb.destroyed_by, ["vkFreeCommandBuffers"]);
}

#[test]
fn the_newer_registry_runs_without_validusage() {
    let l = load(&shared_registry("1.4.309"), true);
    assert!(!l.validity.explicit_known);
    assert!(l.validity.comparison.is_none());
    assert_eq!(l.validity.rules.len(), 6029);
    assert!(l
        .validity
        .rules
        .iter()
        .all(|r| r.category == Category::Implicit));
}

#[test]
fn the_report_tallies_only_the_records_handed_to_it() {
    use tuff_gen::plan::{Record, Settlement};
    use tuff_gen::report;
    let l = pinned();
    let none = report::build(&l.model, &l.validity, &[]);
    assert_eq!(none.emitted.column_total(0), 0);
    assert_eq!(none.emitted.column_total(1), 0);
    assert_eq!(none.emitted.column_total(2), none.emitted.total());

    let records = [
        Record {
            vuid: "VUID-vkCmdDraw-commandBuffer-parameter".into(),
            settlement: Settlement::Static("takes &CommandBuffer".into()),
        },
        Record {
            vuid: "VUID-vkCmdDraw-None-02691".into(),
            settlement: Settlement::Dynamic("checks the bound view's format".into()),
        },
    ];
    let some = report::build(&l.model, &l.validity, &records);
    assert!(some.unknown_records.is_empty());
    let bogus = [Record {
        vuid: "VUID-vkCmdDraw-None-99999".into(),
        settlement: Settlement::Static("nothing".into()),
    }];
    let flagged = report::build(&l.model, &l.validity, &bogus);
    assert_eq!(flagged.unknown_records, ["VUID-vkCmdDraw-None-99999"]);
    assert!(report::render(&flagged)[0]
        .contents
        .contains("VUID-vkCmdDraw-None-99999"));
    assert_eq!(flagged.emitted.column_total(0), 0);
    assert_eq!(some.emitted.counts[0][0], 1, "implicit, static");
    assert_eq!(some.emitted.counts[2][1], 1, "usage, dynamic");
    assert_eq!(some.emitted.total(), none.emitted.total());
    let settled = some
        .settled
        .iter()
        .find(|s| s.rule.vuid == "VUID-vkCmdDraw-commandBuffer-parameter")
        .unwrap();
    assert_eq!(settled.settlement.status(), "static");
    assert_eq!(settled.settlement.mechanism(), "takes &CommandBuffer");
}

/// The checks are data; what the renderer writes for each must agree with what the
/// data says it reads, since the checked methods pass only those arguments and bind
/// the scope only for checks that use it.
#[test]
fn rendered_checks_read_what_their_data_says() {
    use tuff_gen::plan::{Context, Plans};
    let l = pinned();
    let cx = Context::new(&l.model, &l.validity);
    let plans = Plans::build(&cx);
    // The identifiers of the code, outside its string literals.
    let words = |code: String| -> BTreeSet<String> {
        let (mut text, mut in_str, mut escaped) = (String::new(), false, false);
        for c in code.chars() {
            match (in_str, c) {
                (true, '\\') if !escaped => escaped = true,
                (_, '"') if !escaped => {
                    in_str = !in_str;
                    text.push(' ');
                }
                (true, _) => escaped = false,
                (false, c) => text.push(c),
            }
        }
        text.split(|c: char| !(c.is_alphanumeric() || c == '_'))
            .map(str::to_owned)
            .collect()
    };
    let mut checked = 0;
    for plan in plans.ok() {
        for check in plans.checker.command_checks(plan) {
            checked += 1;
            let code = words(tuff_gen::emit::checks::render(check).to_string());
            for arg in check.reads() {
                assert!(
                    code.contains(&arg),
                    "{}: reads `{arg}` but its code does not: {check:?}",
                    plan.name
                );
            }
            assert_eq!(
                check.uses_scope(),
                code.contains("s"),
                "{}: {check:?}",
                plan.name
            );
        }
    }
    assert!(checked > 150, "only {checked} command checks");
}

/// The implicit VUIDs derived from a registry without validusage.json against the
/// list the specification's own toolchain writes for it (`../shared/registry/<v>/
/// implicit-vuids-spec-toolchain.txt`): at least 99.9% agreement both ways, and every
/// difference a checked-in exception with its reason.
fn check_toolchain_agreement(version: &str) {
    let pinned = root().join("tests/registries").join(version);
    let dir = if pinned.is_dir() {
        pinned
    } else {
        shared_registry(version)
    };
    let l = load(&dir, true);
    let derived: BTreeSet<String> = l
        .validity
        .rules
        .iter()
        .filter(|r| r.derived)
        .map(|r| r.vuid.clone())
        .collect();
    let listed: BTreeSet<String> =
        std::fs::read_to_string(dir.join("implicit-vuids-spec-toolchain.txt"))
            .expect("the toolchain's list")
            .lines()
            .map(str::to_owned)
            .collect();
    let both = derived.intersection(&listed).count();
    let only_derived: Vec<&String> = derived.difference(&listed).collect();
    let only_listed: Vec<&String> = listed.difference(&derived).collect();
    println!(
        "{version}: derived {}, listed {}, both {both}, only derived {:?}, only listed {:?}",
        derived.len(),
        listed.len(),
        only_derived,
        only_listed
    );
    assert!(
        listed.len() > 5000,
        "{version}: a list of {} VUIDs",
        listed.len()
    );
    let recall = both as f64 / listed.len() as f64;
    let precision = both as f64 / derived.len() as f64;
    assert!(
        recall >= 0.999,
        "{version}: listed rules derived: {recall:.4}"
    );
    assert!(
        precision >= 0.999,
        "{version}: derived rules listed: {precision:.4}"
    );
    let text =
        std::fs::read_to_string(root().join("generator/derivation-exceptions.toml")).unwrap();
    let file: Exceptions = toml::from_str(&text).unwrap();
    let expected: BTreeSet<(&str, &str)> = file
        .exception
        .iter()
        .filter(|e| e.registry == version)
        .map(|e| (e.side.as_str(), e.vuid.as_str()))
        .collect();
    let actual: BTreeSet<(&str, &str)> = only_listed
        .iter()
        .map(|v| ("listed", v.as_str()))
        .chain(only_derived.iter().map(|v| ("derived", v.as_str())))
        .collect();
    assert_eq!(
        actual, expected,
        "the differences must be exactly the checked-in exceptions of {version}"
    );
}

#[test]
fn derivation_agrees_with_the_toolchain_1_3_281() {
    check_toolchain_agreement("1.3.281");
}

/// 1.4.330's toolchain writes kinds the older ones did not: `-suspended`,
/// `-device-queuecount` and `-parameter` for `VkDeviceAddress` values.
#[test]
fn derivation_agrees_with_the_toolchain_1_4_330() {
    check_toolchain_agreement("1.4.330");
}

/// The newest registry (Vulkan-Docs at 1.4.360, pinned in `tests/registries/`).
#[test]
fn derivation_agrees_with_the_toolchain_1_4_360() {
    check_toolchain_agreement("1.4.360");
}

/// A newer registry keeps every command, struct and handle an older one emits: the
/// 1.4.330 registry, whose core versions are split into internal feature blocks
/// (`VK_BASE_VERSION_1_0`, ...), emits at least what 1.4.309 does, core included.
#[test]
fn a_newer_registry_emits_every_item_the_older_one_does() {
    let older = load(&shared_registry("1.4.309"), true);
    let newer = load(&shared_registry("1.4.330"), true);
    let kept = |l: &Loaded| -> BTreeSet<String> {
        l.model
            .emitted
            .iter()
            .filter(|n| {
                l.model.commands.contains_key(*n)
                    || l.model.types.get(*n).is_some_and(|t| {
                        matches!(
                            t.category,
                            Some(tuff_gen::model::Kind::Struct | tuff_gen::model::Kind::Handle)
                        )
                    })
            })
            .cloned()
            .collect()
    };
    let (old, new) = (kept(&older), kept(&newer));
    let lost: Vec<&String> = old.difference(&new).collect();
    assert!(old.contains("vkCreateBuffer") && new.contains("vkCreateBuffer"));
    assert!(old.len() > 1000, "{} items", old.len());
    assert!(
        lost.is_empty(),
        "1.4.330 lost {} of 1.4.309's items: {lost:?}",
        lost.len()
    );
}

#[test]
fn sync_tables_come_from_registries_that_have_them() {
    let pinned = registry::load_registry(&root().join("vk.xml")).unwrap();
    assert!(pinned.sync.is_none(), "1.3.239 has no <sync> block");
    let reference = registry::load_registry(&root().join("reference/vk.xml")).unwrap();
    let t = reference.sync.expect("1.3.281 has a <sync> block");
    let stage = |n: &str| t.stages.iter().find(|s| s.name == n).expect(n);
    let access = |n: &str| t.accesses.iter().find(|a| a.name == n).expect(n);
    assert_eq!(stage("VK_PIPELINE_STAGE_2_COPY_BIT").bit, 1 << 32);
    assert!(stage("VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT")
        .equivalent
        .contains(&"VK_PIPELINE_STAGE_2_COPY_BIT".to_owned()));
    let read = access("VK_ACCESS_2_TRANSFER_READ_BIT");
    assert!(read
        .stages
        .as_ref()
        .unwrap()
        .contains(&"VK_PIPELINE_STAGE_2_COPY_BIT".to_owned()));
    // MEMORY_READ lists no stage: every stage.
    assert!(access("VK_ACCESS_2_MEMORY_READ_BIT").stages.is_none());
    let graphics = t
        .pipelines
        .iter()
        .find(|p| p.name == "graphics primitive")
        .unwrap();
    let at = |n: &str| graphics.ordered.iter().position(|s| s == n).unwrap();
    assert!(
        at("VK_PIPELINE_STAGE_2_VERTEX_SHADER_BIT") < at("VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT")
    );
}

#[test]
fn the_hazard_trackers_facts_agree_with_every_sync_table() {
    for version in ["1.3.281", "1.4.309", "1.4.330"] {
        let reg = registry::load_registry(&shared_registry(version).join("vk.xml")).unwrap();
        let t = reg.sync.expect("a <sync> block");
        tuff_gen::plan::accesses::check(&t).unwrap_or_else(|e| panic!("{version}: {e}"));
    }
}

#[test]
fn a_fact_the_sync_tables_do_not_allow_stops_the_generator() {
    let reg = registry::load_registry(&root().join("reference/vk.xml")).unwrap();
    let whole = reg.sync.unwrap();
    let mut t = whole.clone();
    // The registry's transfer reads, minus the copy stage the table times copies at
    // (and ALL_TRANSFER, which stands for it).
    let read = t
        .accesses
        .iter_mut()
        .find(|a| a.name == "VK_ACCESS_2_TRANSFER_READ_BIT")
        .unwrap();
    read.stages.as_mut().unwrap().retain(|s| {
        s != "VK_PIPELINE_STAGE_2_COPY_BIT" && s != "VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT"
    });
    let e = tuff_gen::plan::accesses::check(&t).expect_err("refused");
    assert!(
        e.contains("does not allow VK_ACCESS_2_TRANSFER_READ_BIT at VK_PIPELINE_STAGE_2_COPY_BIT"),
        "{e}"
    );
    let mut t = whole;
    t.stages
        .retain(|s| s.name != "VK_PIPELINE_STAGE_2_BLIT_BIT");
    let e = tuff_gen::plan::accesses::check(&t).expect_err("refused");
    assert!(e.contains("no stage VK_PIPELINE_STAGE_2_BLIT_BIT"), "{e}");
}

/// No registry here has a flags type whose declared bits and name disagree; a
/// registry that had one gets it listed (the CLI prints each as a warning), not read
/// by a silent guess: with `VkCullModeFlags`'s `requires` dropped, or pointed at
/// another enum, the note names it.
#[test]
fn a_flags_type_whose_declaration_and_name_disagree_is_listed() {
    let notes = |l: &Loaded| tuff_gen::validity::implicit::bitmask_shape_notes(&l.model);
    for v in ["1.3.239", "1.3.281", "1.4.309", "1.4.330"] {
        assert_eq!(
            notes(&load(&shared_registry(v), true)),
            Vec::<String>::new(),
            "{v}"
        );
    }
    let newest = load(&root().join("tests/registries/1.4.360"), true);
    assert_eq!(notes(&newest), Vec::<String>::new(), "1.4.360");
    let text = std::fs::read_to_string(root().join("vk.xml")).unwrap();
    let declared = r#"<type requires="VkCullModeFlagBits"               category="bitmask">"#;
    assert!(text.contains(declared));
    let opts = tuff_gen::Options::pinned();
    let config = tuff_gen::config::Config::load(&opts.config).unwrap();
    for (edit, says) in [
        (
            r#"<type category="bitmask">"#,
            "`VkCullModeFlags` declares no bits; the specification's toolchain reads `VkCullModeFlagBits` by name, which has values",
        ),
        (
            r#"<type requires="VkFrontFace" category="bitmask">"#,
            "`VkCullModeFlags` declares its bits as `VkFrontFace`; the specification's toolchain reads `VkCullModeFlagBits` by name, which has values",
        ),
    ] {
        let edited = text.replacen(declared, edit, 1);
        let reg = tuff_gen::registry::parse_registry(std::path::Path::new("edited vk.xml"), edited.as_bytes()).unwrap();
        let model = tuff_gen::model::Model::build(&reg, None, &config, &opts.config).unwrap();
        let got = tuff_gen::validity::implicit::bitmask_shape_notes(&model);
        assert_eq!(got.len(), 1, "{got:?}");
        assert!(got[0].starts_with(says), "{got:?}");
    }
}
