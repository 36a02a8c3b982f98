//! Insta snapshots (in `snapshots/`) of the model and the derived rules of a few
//! central items, and of the coverage table.

mod common;

use common::{load, root, Loaded};
use serde::Serialize;
use std::sync::OnceLock;
use tuff_gen::model::{ExternSync, Field, Handle, LenEntry, Model};
use tuff_gen::validity::{implicit, Toolchain};

fn pinned() -> &'static Loaded {
    static L: OnceLock<Loaded> = OnceLock::new();
    L.get_or_init(|| load(&root(), false))
}

#[derive(Serialize)]
struct ItemModel<'a> {
    name: &'a str,
    condition: &'a str,
    emitted: bool,
    returns: Option<&'a str>,
    queues: Option<&'a str>,
    renderpass: Option<&'a str>,
    cmdbufferlevel: Option<&'a str>,
    returned_only: Option<bool>,
    extended_by: Vec<&'a str>,
    fields: Vec<FieldModel>,
    handles_created: Vec<&'a Handle>,
}

/// A field as the model reads it: its declaration and parsed attributes.
#[derive(Serialize)]
struct FieldModel {
    name: String,
    type_name: String,
    category: Option<&'static str>,
    is_const: bool,
    pointers: usize,
    static_array: Option<String>,
    len: Vec<LenEntry>,
    optional: Vec<bool>,
    externsync: Vec<ExternSync>,
    noautovalidity: bool,
}

fn field_model(m: &Model, f: &Field) -> FieldModel {
    FieldModel {
        name: f.name.clone(),
        type_name: f.type_name.clone(),
        category: m.category(&f.type_name).map(|k| k.name()),
        is_const: f.is_const,
        pointers: f.pointers,
        static_array: f.static_array.clone(),
        len: f.parsed.len.clone(),
        optional: f.parsed.optional.clone(),
        externsync: f.parsed.externsync.clone(),
        noautovalidity: f.noautovalidity,
    }
}

fn item_model(name: &str) -> ItemModel<'static> {
    let m = &pinned().model;
    let name = m
        .commands
        .get_key_value(name)
        .map(|(k, _)| k.as_str())
        .or_else(|| m.types.get_key_value(name).map(|(k, _)| k.as_str()))
        .expect("item exists");
    let cmd = m.commands.get(name);
    let ty = m.types.get(name);
    let fields = cmd
        .map(|c| &c.params)
        .or(ty.map(|t| &t.members))
        .unwrap()
        .iter()
        .map(|f| field_model(m, f))
        .collect();
    ItemModel {
        name,
        condition: m.condition(name).text(),
        emitted: m.emitted.contains(name),
        returns: cmd.map(|c| c.return_type.as_str()),
        queues: cmd.and_then(|c| c.queues.as_deref()),
        renderpass: cmd.and_then(|c| c.renderpass.as_deref()),
        cmdbufferlevel: cmd.and_then(|c| c.cmdbufferlevel.as_deref()),
        returned_only: ty.map(|t| t.returned_only),
        extended_by: m
            .extended_by
            .get(name)
            .into_iter()
            .flatten()
            .map(String::as_str)
            .collect(),
        fields,
        handles_created: m
            .handles
            .values()
            .filter(|h| h.created_by.iter().any(|c| c == name))
            .collect(),
    }
}

fn rules(name: &str) -> Vec<String> {
    let m = &pinned().model;
    implicit::derive_item(m, Toolchain::for_version(&m.version), name)
        .into_iter()
        .map(|r| format!("{}: {}", r.vuid, r.text))
        .collect()
}

const ITEMS: [&str; 5] = [
    "vkCreateBuffer",
    "VkBufferCreateInfo",
    "vkCmdDraw",
    "vkQueueSubmit",
    "VkGraphicsPipelineCreateInfo",
];

#[test]
fn models_and_rules_of_central_items() {
    insta::with_settings!({ snapshot_path => "../snapshots", prepend_module_to_snapshot => false }, {
        for item in ITEMS {
            insta::assert_json_snapshot!(format!("model-{item}"), item_model(item));
            insta::assert_json_snapshot!(format!("rules-{item}"), rules(item));
        }
    });
}

#[test]
fn coverage_table() {
    let md = std::fs::read_to_string(root().join("generated/VALIDATION.md")).unwrap();
    let tables: String = md
        .lines()
        .filter(|l| l.starts_with('#') || l.starts_with('|') && !l.starts_with("| `"))
        .take_while(|l| !l.starts_with("## Rules left"))
        .collect::<Vec<_>>()
        .join("\n");
    insta::with_settings!({ snapshot_path => "../snapshots", prepend_module_to_snapshot => false }, {
        insta::assert_snapshot!("coverage-table", tables);
    });
}

/// Methods are named on their receiver by one rule (`names::methods`), and the
/// rule's exceptions hold: a handle's name stays, and so does a name that another
/// method of the same type has.
#[test]
fn methods_are_named_on_their_receiver() {
    let methods = tuff_gen::names::methods(&pinned().model);
    for (command, method) in [
        ("vkQueueSubmit", "submit"),
        ("vkQueueWaitIdle", "wait_idle"),
        ("vkDeviceWaitIdle", "wait_idle"),
        ("vkCmdDraw", "draw"),
        ("vkCmdBeginRenderPass", "begin_render_pass"),
        ("vkGetPhysicalDeviceProperties", "get_properties"),
        ("vkResetCommandBuffer", "reset"),
        ("vkGetDeviceQueue", "get_queue"),
        ("vkQueuePresentKHR", "present_khr"),
        // A display's commands are its own, without its vendor tag's help.
        ("vkReleaseDisplayEXT", "release_ext"),
        ("vkCreateDisplayModeKHR", "create_mode_khr"),
        // Unchanged: not the receiver's name, another handle's, a clash.
        ("vkCreateBuffer", "create_buffer"),
        ("vkWaitForFences", "wait_for_fences"),
        (
            "vkGetDeviceMemoryCommitment",
            "get_device_memory_commitment",
        ),
        (
            "vkGetDeviceBufferMemoryRequirements",
            "get_device_buffer_memory_requirements",
        ),
        ("vkEnumeratePhysicalDevices", "enumerate_physical_devices"),
    ] {
        assert_eq!(methods[command], method, "{command}");
    }
    // A physical device's command that acts on one of its displays is called on
    // the display, which passes its own parent.
    assert_eq!(
        tuff_gen::names::receiver_type(&pinned().model, "vkReleaseDisplayEXT"),
        "VkDisplayKHR"
    );
    assert_eq!(
        tuff_gen::names::receiver_type(&pinned().model, "vkGetPhysicalDeviceDisplayPropertiesKHR"),
        "VkPhysicalDevice"
    );
    // No two commands of one receiver share a method.
    let mut seen = std::collections::BTreeSet::new();
    for (command, method) in &methods {
        let receiver = tuff_gen::names::receiver_type(&pinned().model, command);
        assert!(
            seen.insert((receiver, method.as_str())),
            "{receiver}::{method} twice"
        );
    }
}

/// The per-method table of the report puts first the methods whose commands the
/// scenes use: by their ash name in the raw-ash programs, or by the method on a
/// receiver of its type in the tuff ones; not a method of another type that shares
/// the name.
#[test]
fn the_report_marks_the_methods_the_scenes_use() {
    let text = std::fs::read_to_string(root().join("generated/VALIDATION.md")).expect("report");
    let scenes = |method: &str| {
        let row = text
            .lines()
            .find(|l| l.starts_with(&format!("| `{method}` |")))
            .unwrap_or_else(|| panic!("no row for {method}"));
        row.split('|').nth(2).map(str::trim) == Some("yes")
    };
    assert!(scenes("Recorder::draw"));
    assert!(scenes("Queue::submit"));
    assert!(scenes("PhysicalDevice::get_memory_properties"));
    assert!(!scenes("Recorder::draw_mesh_tasks_ext"));
}
