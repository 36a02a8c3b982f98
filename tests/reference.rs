//! The reference registry: extensions the registry `ash` is generated from defines
//! otherwise are left out of the emitted API with the reason, and nothing else is;
//! what it lacks the crate defines itself (the delta).

mod common;

use common::{cli, root};
use tuff_gen::model::reference::select;
use tuff_gen::registry::{load_registry, Registry};

fn registries() -> (Registry, Registry) {
    let pinned = load_registry(&root().join("vk.xml")).expect("pinned registry");
    let reference = load_registry(&root().join("reference/vk.xml")).expect("reference");
    (pinned, reference)
}

fn versions() -> Vec<String> {
    (0..=3).map(|m| format!("VK_VERSION_1_{m}")).collect()
}

#[test]
fn every_extension_ash_lacks_or_defines_otherwise_is_left_out_with_its_reason() {
    let (pinned, reference) = registries();
    let all: Vec<String> = pinned
        .extensions
        .iter()
        .filter(|e| {
            e.supported
                .as_deref()
                .is_some_and(|s| s.split(',').any(|a| a == "vulkan"))
        })
        .map(|e| e.name.clone())
        .collect();
    let (kept, left) = select(&pinned, Some(&reference), &versions(), &all);
    let reasons: Vec<(&str, &str)> = left
        .iter()
        .map(|l| (l.name.as_str(), l.reason.as_str()))
        .collect();
    let names: Vec<&str> = reasons.iter().map(|(n, _)| *n).collect();
    assert_eq!(
        names,
        [
            // Members were added or renamed before 1.3.281.
            "VK_EXT_device_fault",
            // The provisional H.264 and H.265 encoders (replaced by KHR ones) need
            // the encode queue as 1.3.239 defined it.
            "VK_EXT_video_encode_h264",
            "VK_EXT_video_encode_h265",
            "VK_HUAWEI_cluster_culling_shader",
            "VK_KHR_video_encode_queue",
        ]
    );
    assert!(reasons[0]
        .1
        .contains("VkDeviceFaultVendorBinaryHeaderVersionOneEXT"));
    assert!(reasons[1]
        .1
        .contains("depends on `VK_KHR_video_encode_queue`"));
    assert!(reasons[4].1.contains("`VkBuffer dstBuffer` there"));
    assert_eq!(kept.len() + left.len(), all.len());
    // Aliases resolved: the EXT names 1.3.281 made aliases of KHR ones are kept.
    for name in ["VK_EXT_calibrated_timestamps", "VK_EXT_line_rasterization"] {
        assert!(kept.iter().any(|k| k == name), "{name} was left out");
    }
    // Without a reference, everything wanted is kept.
    let (kept, left) = select(&pinned, None, &versions(), &all);
    assert_eq!((kept.len(), left.len()), (all.len(), 0));
}

#[test]
fn an_extension_ash_lacks_stays_and_one_that_depends_on_one_left_out_goes() {
    let (pinned, reference) = registries();
    let wanted: Vec<String> = ["VK_KHR_surface", "VK_KHR_swapchain", "VK_EXT_debug_utils"]
        .map(String::from)
        .to_vec();
    // A reference without VK_KHR_surface: the extension stays (the crate defines
    // what ash lacks, `missing_items`), and so does VK_KHR_swapchain.
    let mut lacking = reference.clone();
    lacking.extensions.retain(|e| e.name != "VK_KHR_surface");
    let (kept, left) = select(&pinned, Some(&lacking), &versions(), &wanted);
    assert_eq!((kept.len(), left.len()), (3, 0), "{left:?}");
    // A reference that defines VkSurfaceFormatKHR otherwise: VK_KHR_surface goes,
    // and VK_KHR_swapchain, which depends on it, with it.
    let mut otherwise = reference;
    let format = otherwise
        .types
        .iter_mut()
        .find(|t| t.name == "VkSurfaceFormatKHR")
        .unwrap();
    format.members[1].name = "colourSpace".into();
    let (kept, left) = select(&pinned, Some(&otherwise), &versions(), &wanted);
    assert_eq!(kept, ["VK_EXT_debug_utils"], "{left:?}");
    assert_eq!(left[0].name, "VK_KHR_surface");
    assert!(left[0].reason.contains("VkSurfaceFormatKHR"), "{left:?}");
    assert_eq!(left[1].name, "VK_KHR_swapchain");
    assert!(
        left[1].reason.contains("depends on `VK_KHR_surface`"),
        "{left:?}"
    );
    // A dependency the config never asked for is not a reason to leave one out:
    // the model refuses that config with its own error.
    let (kept, left) = select(&pinned, Some(&otherwise), &versions(), &wanted[1..]);
    assert_eq!((kept.len(), left.len()), (2, 0), "{left:?}");
}

#[test]
fn the_pinned_config_lists_what_it_leaves_out_with_the_reason() {
    let report = std::fs::read_to_string(root().join("generated/VALIDATION.md")).unwrap();
    let section = report
        .split("## Left out: what ash lacks")
        .nth(1)
        .expect("the report has the section")
        .split("\n## ")
        .next()
        .unwrap();
    assert!(section.contains("(Vulkan 1.3.281)"));
    // Every extension of the pinned registry is asked for; those ash's registry
    // lacks (the provisional video encode extensions of 1.3.239) or defines
    // otherwise are listed, each with why, and nothing else.
    let rows: Vec<&str> = section.lines().filter(|l| l.starts_with("| `")).collect();
    for name in [
        "VK_EXT_video_encode_h264",
        "VK_EXT_video_encode_h265",
        "VK_KHR_video_encode_queue",
    ] {
        assert!(
            rows.iter()
                .any(|r| r.starts_with(&format!("| `{name}` | "))),
            "{name} is not listed: {rows:?}"
        );
    }
    assert!(rows.len() < 10, "{rows:?}");
    assert!(rows
        .iter()
        .all(|r| r.split(" | ").nth(1).is_some_and(|why| why.len() > 20)));
}

#[test]
fn a_missing_reference_registry_is_named() {
    let dir = tempfile::tempdir().unwrap();
    let cfg = dir.path().join("tuff-gen.toml");
    std::fs::write(
        &cfg,
        "api_version = \"1.3\"\nreference_registry = \"nope/vk.xml\"\n",
    )
    .unwrap();
    let out = dir.path().join("out");
    let (code, _, stderr) = cli(&[
        "--config",
        &cfg.display().to_string(),
        "--out",
        &out.display().to_string(),
    ]);
    assert_ne!(code, 0);
    assert!(stderr.contains("nope/vk.xml"), "{stderr}");
    assert!(!out.exists(), "nothing is written");
}

#[test]
fn the_report_breaks_the_emitted_api_down_by_version_and_extension() {
    let report = std::fs::read_to_string(root().join("generated/VALIDATION.md")).unwrap();
    let section = report
        .split("## Per version and extension (emitted API)")
        .nth(1)
        .expect("the report has the section")
        .split("\n## ")
        .next()
        .unwrap();
    // "settled of total" cells: implicit, creation, usage.
    let cells = |row: &str| -> Vec<(usize, usize)> {
        row.split(" | ")
            .filter_map(|c| {
                let (settled, total) = c
                    .trim_matches(|ch| ch == '|' || ch == ' ')
                    .split_once(" of ")?;
                Some((settled.parse().ok()?, total.parse().ok()?))
            })
            .collect()
    };
    let rows: Vec<(&str, Vec<(usize, usize)>)> = section
        .lines()
        .filter(|l| l.starts_with("| ") && !l.starts_with("| Version"))
        .map(|l| (l.split(" | ").next().unwrap_or(""), cells(l)))
        .collect();
    assert!(rows.iter().all(|(_, c)| c.len() == 3), "{rows:?}");
    assert!(rows.iter().any(|(name, _)| *name == "| `VK_KHR_swapchain`"));
    assert!(rows.iter().any(|(name, _)| *name == "| Vulkan 1.3"));
    // The rows add up to the emitted API's table.
    let emitted = report
        .split("## Emitted API")
        .nth(1)
        .expect("the emitted table")
        .lines()
        .find(|l| l.starts_with("| Implicit |"))
        .expect("its implicit row")
        .split(" | ")
        .map(|c| c.trim_matches(|ch| ch == '|' || ch == ' ').to_owned())
        .collect::<Vec<_>>();
    let (settled, total): (usize, usize) = rows
        .iter()
        .map(|(_, c)| c[0])
        .fold((0, 0), |(s, t), (a, b)| (s + a, t + b));
    assert_eq!(total.to_string(), emitted[4]);
    let static_dynamic: usize =
        emitted[1].parse::<usize>().unwrap() + emitted[2].parse::<usize>().unwrap();
    assert_eq!(settled, static_dynamic);
}

/// A registry newer than ash's: 1.4.309 renames what 1.4 promoted
/// (`VkPhysicalDevicePushDescriptorPropertiesKHR` is an alias of the 1.4 name), adds
/// items to extensions ash has, and moves two commands to other extensions' require
/// blocks. With core up to 1.3, the emitted API names each item as ash does, and
/// leaves out only what ash lacks, each item with its reason.
#[test]
fn a_newer_registry_is_emitted_by_the_names_ash_has_and_loses_only_what_ash_lacks() {
    let newer = load_registry(&root().join("../shared/registry/1.4.309/vk.xml"))
        .expect("the 1.4.309 registry");
    let (_, reference) = registries();
    let config = tuff_gen::config::Config {
        api_version: "1.3".to_owned(),
        all_extensions: true,
        ..Default::default()
    };
    let model = tuff_gen::model::Model::build(
        &newer,
        Some(&reference),
        &config,
        std::path::Path::new("test.toml"),
    )
    .expect("the model builds");
    let left: Vec<(&str, &str)> = model
        .left_out
        .iter()
        .map(|l| (l.name.as_str(), l.reason.as_str()))
        .collect();
    let reason = |name: &str| {
        left.iter()
            .find(|(n, _)| *n == name)
            .map(|(_, r)| *r)
            .unwrap_or_else(|| panic!("{name} is not left out: {left:?}"))
    };
    // Kept although 1.4 renamed their types or added to them: aliases on both sides
    // and array sizes by value compare alike, and what only the newer registry has
    // goes alone.
    for kept in [
        "VK_KHR_push_descriptor",
        "VK_EXT_line_rasterization",
        "VK_KHR_global_priority",
        "VK_KHR_ray_tracing_pipeline",
        "VK_NV_optical_flow",
        "VK_NVX_binary_import",
    ] {
        assert!(
            model.enabled.contains(kept),
            "{kept} left out: {:?}",
            left.iter().find(|(n, _)| *n == kept)
        );
    }
    // A struct ash lacks whose members ash can spell is defined by the crate (the
    // delta), not left out.
    assert!(!left
        .iter()
        .any(|(n, _)| *n == "VkCuModuleTexturingModeCreateInfoNVX"));
    assert!(model.delta.contains("VkCuModuleTexturingModeCreateInfoNVX"));
    assert!(model
        .emitted
        .contains("VkCuModuleTexturingModeCreateInfoNVX"));
    assert!(reason("vkGetImageViewHandle64NVX").contains("has no command"));
    assert!(reason("vkCmdWriteBufferMarker2AMD")
        .contains("function table of `VK_KHR_synchronization2`"));
    assert!(!model.emitted.contains("vkCmdWriteBufferMarker2AMD"));
    // Named as ash names them.
    assert_eq!(
        model.spelling("VkPhysicalDevicePushDescriptorProperties"),
        "VkPhysicalDevicePushDescriptorPropertiesKHR"
    );
    assert_eq!(
        model.spelling("vkCmdPushDescriptorSet"),
        "vkCmdPushDescriptorSetKHR"
    );
    assert_eq!(
        model.name_in(
            "vkGetCalibratedTimestampsKHR",
            "VK_EXT_calibrated_timestamps"
        ),
        "vkGetCalibratedTimestampsEXT"
    );
    // A config asking for core 1.4, which ash has no table for: the version is
    // emitted, its commands through the crate's own table, its items named as ash
    // names them (the extension aliases they were promoted from), and the two ash
    // lacks altogether left out, each with its reason.
    let v14 = tuff_gen::config::Config {
        api_version: "1.4".to_owned(),
        ..config.clone()
    };
    let m14 = tuff_gen::model::Model::build(
        &newer,
        Some(&reference),
        &v14,
        std::path::Path::new("test.toml"),
    )
    .expect("the model builds");
    assert!(m14.enabled.contains("VK_VERSION_1_4"));
    assert_eq!(m14.own_tables, [4].into_iter().collect());
    assert_eq!(
        tuff_gen::names::table(&m14, "vkCmdPushDescriptorSet"),
        Some(tuff_gen::names::Table::Own(4))
    );
    // Typed by ash's PFN of the name it knows the command by, which is no alias
    // there (vkCmdSetLineStippleEXT is one of vkCmdSetLineStippleKHR in 1.3.281).
    assert_eq!(
        m14.spelling("vkCmdPushDescriptorSet"),
        "vkCmdPushDescriptorSetKHR"
    );
    assert_eq!(
        m14.spelling("vkCmdSetLineStipple"),
        "vkCmdSetLineStippleKHR"
    );
    assert_eq!(
        tuff_gen::names::methods(&m14)["vkCmdPushDescriptorSet"],
        "push_descriptor_set"
    );
    // The 19 commands of 1.4 are all emitted.
    let core14 = [
        "vkMapMemory2",
        "vkUnmapMemory2",
        "vkGetDeviceImageSubresourceLayout",
        "vkGetImageSubresourceLayout2",
        "vkCopyMemoryToImage",
        "vkCopyImageToMemory",
        "vkCopyImageToImage",
        "vkTransitionImageLayout",
        "vkCmdPushDescriptorSet",
        "vkCmdPushDescriptorSetWithTemplate",
        "vkCmdBindDescriptorSets2",
        "vkCmdPushConstants2",
        "vkCmdPushDescriptorSet2",
        "vkCmdPushDescriptorSetWithTemplate2",
        "vkCmdSetLineStipple",
        "vkCmdBindIndexBuffer2",
        "vkGetRenderingAreaGranularity",
        "vkCmdSetRenderingAttachmentLocations",
        "vkCmdSetRenderingInputAttachmentIndices",
    ];
    for c in core14 {
        assert!(m14.emitted.contains(c), "{c} is not emitted");
    }
    // The two structs of 1.4 ash lacks altogether are the crate's own, in ash's
    // style; nothing of 1.4 is left out.
    assert!(!m14.left_out.iter().any(|l| l.name.contains("Vulkan14")));
    for d in [
        "VkCuModuleTexturingModeCreateInfoNVX",
        "VkPhysicalDeviceVulkan14Features",
        "VkPhysicalDeviceVulkan14Properties",
    ] {
        assert!(m14.delta.contains(d), "{d} is not in the delta");
    }
    // The extensions ash lacks altogether are emitted: their structs, unions, enums,
    // flags and handles are the delta, their commands in the crate's own tables;
    // only what cannot be spelled goes, each with its reason (a C bit field).
    assert!(m14.own_extensions.contains("VK_KHR_pipeline_binary"));
    assert!(m14.enabled.contains("VK_KHR_pipeline_binary"));
    for d in [
        "VkPipelineBinaryKHR",
        "VkPipelineBinaryCreateInfoKHR",
        "VkPhysicalDeviceLayeredApiKHR",
        "VkIndirectCommandsInputModeFlagsEXT",
        "VkIndirectCommandsTokenDataEXT",
    ] {
        assert!(m14.delta.contains(d), "{d} is not in the delta");
        assert!(m14.emitted.contains(d), "{d} is not emitted");
    }
    assert!(m14.delta_commands.contains("vkCreatePipelineBinariesKHR"));
    assert!(m14
        .delta_commands
        .contains("vkCmdExecuteGeneratedCommandsEXT"));
    let left14 = |name: &str| {
        m14.left_out
            .iter()
            .find(|l| l.name == name)
            .map(|l| l.reason.as_str())
            .unwrap_or_else(|| panic!("{name} is not left out"))
    };
    assert!(left14("VkClusterAccelerationStructureInstantiateClusterInfoNV").contains("bit field"));
    assert!(!m14
        .left_out
        .iter()
        .any(|l| l.reason.contains("has no such extension")));
    for s in [
        "VkPhysicalDeviceVulkan14Features",
        "VkPhysicalDeviceVulkan14Properties",
    ] {
        assert!(m14.emitted.contains(s), "{s} is not emitted");
    }
    // Values 1.4 adds or names anew that ash lacks by name: the delta defines them
    // and the checks accept them by number.
    assert!(m14.delta_values["VkIndexType"].contains(&"VK_INDEX_TYPE_UINT8".to_owned()));
    assert!(m14.delta_values["VkSubgroupFeatureFlagBits"]
        .contains(&"VK_SUBGROUP_FEATURE_ROTATE_BIT".to_owned()));
    assert!(m14.delta_values["VkStructureType"]
        .contains(&"VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_4_FEATURES".to_owned()));
    assert!(!m14.left_out.iter().any(|l| l.name == "VK_VERSION_1_4"));
    // The pinned registry needs no other spelling.
    let (pinned, _) = registries();
    let model = tuff_gen::model::Model::build(
        &pinned,
        Some(&reference),
        &config,
        std::path::Path::new("test.toml"),
    )
    .expect("the model builds");
    assert!(model.spellings.is_empty(), "{:?}", model.spellings);
}

/// A struct the pinned registry does not mark `returnedonly` but the reference does
/// (Khronos's correction, which drops its members' value rules) is one Vulkan only
/// writes, where the emitted API also passes it only as storage to fill: it gets no
/// setters. A struct the reference leaves as it is (the Metal export structs, which
/// name the memory or image to export) is not one.
#[test]
fn structs_the_reference_marks_returned_only_are_written_by_vulkan_alone() {
    let (pinned, reference) = registries();
    let config = tuff_gen::config::Config {
        api_version: "1.3".to_owned(),
        all_extensions: true,
        ..Default::default()
    };
    let build = |reference: Option<&Registry>| {
        tuff_gen::model::Model::build(&pinned, reference, &config, std::path::Path::new("t.toml"))
            .expect("the model builds")
    };
    let model = build(Some(&reference));
    let facts = tuff_gen::plan::types::TypeFacts::new(&model);
    let written: Vec<&str> = facts.written.iter().map(String::as_str).collect();
    for name in [
        "VkCooperativeMatrixPropertiesNV",
        "VkQueueFamilyGlobalPriorityPropertiesKHR",
        "VkPerformanceValueINTEL",
    ] {
        assert!(written.contains(&name), "{name} missing from {written:?}");
    }
    for name in &written {
        assert!(model.returned_only_in_reference.contains(*name), "{name}");
    }
    assert!(!written.contains(&"VkExportMetalBufferInfoEXT"));
    assert!(!written.contains(&"VkPhysicalDeviceExtendedDynamicState3PropertiesEXT"));
    // Without a reference there is no correction to follow.
    assert!(tuff_gen::plan::types::TypeFacts::new(&build(None))
        .written
        .is_empty());
}
