//! Proof of layout: every item the 1.4 crate defines because ash lacks it
//! (`tuff::vk`'s delta: structs, unions, enums, flags types, handles, `API_VERSION_1_4`,
//! array sizes, enum values ash lacks by name) against the
//! C headers of the same registry (Vulkan-Headers v1.4.309, `headers/`), compiled
//! with the `cc` crate: each struct's size, alignment and every member's offset, and
//! each constant's value. The count is compared with the one the generator printed
//! (`target/core14/gen.log`, written by `scripts/core14.sh`).

use std::collections::BTreeMap;
use std::fmt::Write as _;
use std::path::Path;
use tuff::vk::delta_layout::{LAYOUT, VALUES};

/// The C program: one line per struct (`name size align`), per member
/// (`name.member offset`) and per constant (`name value`).
fn probe() -> String {
    let mut c = String::from(
        // Beta extensions' values too, and the one platform header whose extension
        // (VK_EXT_external_memory_metal) ash lacks: the crate emits every extension.
        "#define VK_ENABLE_BETA_EXTENSIONS\n#include <stddef.h>\n#include <stdio.h>\n#include <vulkan/vulkan_core.h>\n#include <vulkan/vulkan_metal.h>\nint main(void) {\n",
    );
    for row in LAYOUT {
        let n = row.c_name;
        let _ = writeln!(
            c,
            "  printf(\"{n} %zu %zu\\n\", sizeof({n}), _Alignof({n}));"
        );
        for (field, _) in row.fields {
            let _ = writeln!(
                c,
                "  printf(\"{n}.{field} %zu\\n\", offsetof({n}, {field}));"
            );
        }
    }
    for (name, _) in VALUES {
        let _ = writeln!(c, "  printf(\"{name} %lld\\n\", (long long)({name}));");
    }
    c.push_str("  return 0;\n}\n");
    c
}

#[test]
fn every_delta_item_is_laid_out_as_the_c_headers_say() {
    let here = Path::new(env!("CARGO_MANIFEST_DIR"));
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join("layout");
    std::fs::create_dir_all(&dir).unwrap();
    let source = dir.join("probe.c");
    std::fs::write(&source, probe()).unwrap();
    let exe = dir.join("probe");
    let compiler = cc::Build::new()
        .target(env!("CORE14_TARGET"))
        .host(env!("CORE14_HOST"))
        .opt_level(0)
        .cargo_metadata(false)
        .warnings(true)
        .include(here.join("headers"))
        .get_compiler();
    let built = compiler
        .to_command()
        .arg("-std=c11")
        .arg(&source)
        .arg("-o")
        .arg(&exe)
        .output()
        .expect("run the C compiler");
    assert!(
        built.status.success(),
        "the probe does not compile: {}",
        String::from_utf8_lossy(&built.stderr)
    );
    let ran = std::process::Command::new(&exe).output().unwrap();
    assert!(ran.status.success());
    let c: BTreeMap<String, Vec<u64>> = String::from_utf8(ran.stdout)
        .unwrap()
        .lines()
        .map(|l| {
            let mut words = l.split(' ');
            let name = words.next().unwrap().to_owned();
            (
                name,
                words.map(|w| w.parse::<i64>().unwrap() as u64).collect(),
            )
        })
        .collect();
    let mut compared = 0;
    for row in LAYOUT {
        assert_eq!(
            c[row.c_name],
            [row.size as u64, row.align as u64],
            "{}: size and alignment (C, Rust)",
            row.c_name
        );
        for (field, offset) in row.fields {
            assert_eq!(
                c[&format!("{}.{field}", row.c_name)],
                [*offset as u64],
                "{}.{field}: offset (C, Rust)",
                row.c_name
            );
        }
        compared += 1;
    }
    for (name, value) in VALUES {
        assert_eq!(c[*name], [*value as u64], "{name} (C, Rust)");
        compared += 1;
    }
    let members: usize = LAYOUT.iter().map(|r| r.fields.len()).sum();
    println!(
        "{compared} delta items laid out as the C headers say: {} types ({members} members), {} constants",
        LAYOUT.len(),
        VALUES.len()
    );
    // The generator's own count of what it defined.
    let log = std::fs::read_to_string(here.join("../../target/core14/gen.log"))
        .expect("scripts/core14.sh writes the generator's output there");
    let line = log
        .lines()
        .find(|l| l.starts_with("tuff-gen: delta: "))
        .expect("the generator reports its delta");
    let reported: usize = line["tuff-gen: delta: ".len()..]
        .split(' ')
        .next()
        .unwrap()
        .parse()
        .unwrap();
    assert_eq!(compared, reported, "{line}");
    assert!(compared > 0, "no delta item: is this the 1.4 crate?");
}

/// The delta works with ash as ash's own items do: a 1.4 struct chains into ash's
/// `PhysicalDeviceFeatures2` (ash's `Extends` trait), has its `sType` by default, and
/// values 1.4 names by core names are ash's values of the same number.
#[test]
fn the_delta_chains_with_ash_and_names_core_values() {
    use tuff::vk;
    use tuff::vk::{IndexTypeDelta as _, StructureTypeDelta as _};
    let mut v14 = vk::PhysicalDeviceVulkan14Features::default().push_descriptor(true);
    assert_eq!(
        v14.s_type,
        vk::StructureType::PHYSICAL_DEVICE_VULKAN_1_4_FEATURES
    );
    let features = vk::PhysicalDeviceFeatures2::default().push_next(&mut v14);
    assert!(!features.p_next.is_null());
    assert_eq!(vk::IndexType::UINT8, vk::IndexType::UINT8_EXT);
    assert_eq!(v14.push_descriptor, vk::TRUE);
}

/// What the delta defines for the extensions ash lacks altogether works as ash's
/// items do: a handle is ash's `Handle` with its object type, an enum and a flags
/// type have their values (the flags with ash's operations), and the extension's
/// function table is there to load.
#[test]
fn the_delta_defines_what_extensions_ash_lacks_need() {
    use tuff::vk;
    use tuff::vk::Handle as _;
    // VK_KHR_pipeline_binary: a new handle.
    assert_eq!(
        <vk::PipelineBinaryKHR as vk::Handle>::TYPE.as_raw(),
        1_000_483_000
    );
    assert_eq!(vk::PipelineBinaryKHR::from_raw(7).as_raw(), 7);
    assert!(vk::PipelineBinaryKHR::null().as_raw() == 0);
    // VK_KHR_maintenance7: a new enum, shown by name.
    assert_eq!(vk::PhysicalDeviceLayeredApiKHR::VULKAN.as_raw(), 0);
    assert_eq!(
        format!("{:?}", vk::PhysicalDeviceLayeredApiKHR::METAL),
        "METAL"
    );
    // VK_EXT_device_generated_commands: a new flags type with ash's operations.
    let modes = vk::IndirectCommandsInputModeFlagsEXT::VULKAN_INDEX_BUFFER
        | vk::IndirectCommandsInputModeFlagsEXT::DXGI_INDEX_BUFFER;
    assert!(modes.contains(vk::IndirectCommandsInputModeFlagsEXT::DXGI_INDEX_BUFFER));
    assert_eq!(modes.as_raw(), 0b11);
    assert_eq!(
        format!("{modes:?}"),
        "VULKAN_INDEX_BUFFER | DXGI_INDEX_BUFFER"
    );
    // Its function tables, under ash's module path.
    let _: Option<vk::khr::pipeline_binary::DeviceFn> = None;
    let _: Option<vk::ext::device_generated_commands::DeviceFn> = None;
}
