//! `tuff-gen diff`: its counts against counts taken from the files themselves, by
//! other means than the generator's parsers.

mod common;

use common::{cli, root, shared_registry};
use std::collections::{BTreeMap, BTreeSet};
use std::path::Path;

/// Every `"vuid"` string of a validusage.json, walked as plain JSON.
fn vuids(path: &Path) -> BTreeSet<String> {
    fn walk(v: &serde_json::Value, out: &mut BTreeSet<String>) {
        match v {
            serde_json::Value::Object(m) => {
                for (k, x) in m {
                    match (k.as_str(), x) {
                        ("vuid", serde_json::Value::String(s)) => {
                            out.insert(s.clone());
                        }
                        _ => walk(x, out),
                    }
                }
            }
            serde_json::Value::Array(a) => a.iter().for_each(|x| walk(x, out)),
            _ => {}
        }
    }
    let text = std::fs::read_to_string(path).expect("validusage.json");
    let json: serde_json::Value = serde_json::from_str(&text).expect("JSON");
    let mut out = BTreeSet::new();
    walk(&json, &mut out);
    out
}

/// The extensions a vk.xml supports for the vulkan API, read off its
/// `<extension ...>` tags as text.
fn extensions(path: &Path) -> BTreeSet<String> {
    let text = std::fs::read_to_string(path).expect("vk.xml");
    let attr = |tag: &str, name: &str| -> Option<String> {
        let start = tag.find(&format!(" {name}=\""))? + name.len() + 3;
        Some(tag[start..start + tag[start..].find('"')?].to_owned())
    };
    text.split("<extension ")
        .skip(1)
        .filter_map(|rest| {
            // The split ate the space before the first attribute.
            let tag = format!(" {}", &rest[..rest.find('>')?]);
            let tag = tag.as_str();
            let supported = attr(tag, "supported")?;
            supported
                .split(',')
                .any(|a| a == "vulkan")
                .then(|| attr(tag, "name"))?
        })
        .collect()
}

#[test]
fn the_diff_of_two_registries_counts_what_the_files_say() {
    let old = root().join("vk.xml");
    let new = shared_registry("1.4.309").join("vk.xml");
    // A small emitted API keeps the two generations quick; the rules and items
    // compared do not depend on it.
    let dir = tempfile::tempdir().unwrap();
    let config = dir.path().join("tuff-gen.toml");
    std::fs::write(&config, "api_version = \"1.0\"\n").unwrap();
    let (code, out, err) = cli(&[
        "diff",
        &old.display().to_string(),
        &new.display().to_string(),
        "--config",
        &config.display().to_string(),
        "--json",
    ]);
    assert_eq!(code, 0, "{err}");
    let d: serde_json::Value = serde_json::from_str(&out).expect("the diff is JSON");
    assert_eq!(d["old_version"], "1.3.239");
    assert_eq!(d["new_version"], "1.4.309");

    // What moved to core and what is new: Vulkan 1.4 is the one version 1.4.309 adds.
    let core = d["core"].as_array().expect("core versions");
    assert_eq!(core.len(), 1, "{core:?}");
    let v14 = &core[0];
    assert_eq!(v14["name"], "VK_VERSION_1_4");
    let names = |v: &serde_json::Value| -> BTreeSet<String> {
        v.as_array()
            .unwrap()
            .iter()
            .map(|x| x.as_str().unwrap().to_owned())
            .collect()
    };
    let promoted = names(&v14["promoted_extensions"]);
    assert!(
        promoted.contains("VK_KHR_push_descriptor") && promoted.contains("VK_KHR_maintenance5")
    );
    let moved: BTreeMap<String, BTreeSet<String>> = v14["moved"]
        .as_array()
        .unwrap()
        .iter()
        .map(|m| (m["core"].as_str().unwrap().to_owned(), names(&m["was"])))
        .collect();
    // Promoted from an extension 1.3.239 had: the extension's names.
    assert_eq!(
        moved["vkCmdPushDescriptorSet"],
        BTreeSet::from(["vkCmdPushDescriptorSetKHR".to_owned()])
    );
    assert!(moved["VK_INDEX_TYPE_UINT8"].contains("VK_INDEX_TYPE_UINT8_EXT"));
    // New with 1.4, or from an extension newer than 1.3.239.
    let new_in_core = names(&v14["new"]);
    for item in [
        "VkPhysicalDeviceVulkan14Features",
        "VK_API_VERSION_1_4",
        "vkCmdBindIndexBuffer2",
        "vkMapMemory2",
    ] {
        assert!(new_in_core.contains(item), "{item} is new");
    }
    assert!(moved.keys().all(|k| !new_in_core.contains(k)));

    let (a, b) = (
        vuids(&root().join("validusage.json")),
        vuids(&shared_registry("1.4.309").join("validusage.json")),
    );
    let count = |v: &serde_json::Value| v.as_array().map_or(usize::MAX, Vec::len);
    assert_eq!(count(&d["rules"]["added"]), b.difference(&a).count());
    assert_eq!(count(&d["rules"]["removed"]), a.difference(&b).count());
    assert!(
        b.difference(&a).count() > 1000,
        "1.4 adds thousands of rules"
    );
    assert!(count(&d["rules"]["text_changed"]) > 0);

    let (x, y) = (extensions(&old), extensions(&new));
    let ext = d["items"]
        .as_array()
        .unwrap()
        .iter()
        .find(|c| c["kind"] == "extensions")
        .expect("extensions are compared");
    let added: BTreeSet<String> = ext["added"]
        .as_array()
        .unwrap()
        .iter()
        .map(|e| e.as_str().unwrap().to_owned())
        .collect();
    assert_eq!(added, y.difference(&x).cloned().collect::<BTreeSet<_>>());
    assert!(added.contains("VK_KHR_maintenance5"));
    assert_eq!(
        count(&ext["removed"]),
        x.difference(&y).count(),
        "{:?}",
        ext["removed"]
    );

    // The emitted API of each side: its coverage table and methods.
    let implicit = |side: &str| -> usize {
        d["emitted"][side][0]
            .as_array()
            .unwrap()
            .iter()
            .map(|n| n.as_u64().unwrap() as usize)
            .sum()
    };
    assert!(
        implicit("old") > 100 && implicit("new") > 100,
        "{}",
        d["emitted"]
    );
    // Signatures are compared as rustfmt writes them.
    let changed = d["emitted"]["signatures_changed"].as_array().unwrap();
    assert!(changed
        .iter()
        .all(|c| c["old"] != c["new"] && c["old"].as_str().unwrap().contains("fn ")));

    // The Markdown form says the same counts.
    let (code, md, err) = cli(&[
        "diff",
        &old.display().to_string(),
        &new.display().to_string(),
        "--config",
        &config.display().to_string(),
    ]);
    assert_eq!(code, 0, "{err}");
    assert!(md.starts_with("# Vulkan 1.3.239 -> 1.4.309"), "{md}");
    assert!(md.contains(&format!(
        "{} added, {} removed, ",
        b.difference(&a).count(),
        a.difference(&b).count()
    )));
    assert!(md.contains(&format!(
        "| extensions | {} | {} |",
        added.len(),
        x.difference(&y).count()
    )));
}

#[test]
fn a_diff_without_rules_on_one_side_says_so() {
    let dir = tempfile::tempdir().unwrap();
    let config = dir.path().join("tuff-gen.toml");
    std::fs::write(&config, "api_version = \"1.0\"\n").unwrap();
    let (code, out, err) = cli(&[
        "diff",
        &shared_registry("1.4.309")
            .join("vk.xml")
            .display()
            .to_string(),
        &shared_registry("1.4.330")
            .join("vk.xml")
            .display()
            .to_string(),
        "--config",
        &config.display().to_string(),
    ]);
    assert_eq!(code, 0, "{err}");
    assert!(out.contains("Not compared: "), "{out}");
    assert!(
        out.contains("1.4.330/vk.xml has no validusage.json"),
        "{out}"
    );
}
