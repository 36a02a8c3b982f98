//! Conversion of vk-parse's tree into the registry pass's plain data.

use super::{is_vulkan_api, CommandDef, EnumGroup, Field, Interface, Registry, Require, TypeDef};
use crate::error::{Error, Result};
use std::collections::BTreeMap;
use std::path::Path;
use vk_parse as vk;

pub(crate) fn convert(path: &Path, parsed: vk::Registry) -> Result<Registry> {
    let mut reg = Registry::default();
    let mut numbers: BTreeMap<String, i64> = BTreeMap::new();
    let mut aliases: Vec<(String, String)> = Vec::new();
    let internal = internal_features(&parsed);
    let mut sync = None;
    for child in parsed.0 {
        match child {
            vk::RegistryChild::Types(types) => {
                for t in types.children {
                    if let vk::TypesChild::Type(t) = t {
                        if is_vulkan_api(t.api.as_deref()) {
                            reg.types.extend(convert_type(t));
                        }
                    }
                }
            }
            vk::RegistryChild::Enums(enums) => {
                if let Some(name) = enums.name {
                    let values = enums
                        .children
                        .into_iter()
                        .filter_map(|c| match c {
                            vk::EnumsChild::Enum(e) if is_vulkan_api(e.api.as_deref()) => {
                                note_number(&mut numbers, &mut aliases, &e, None);
                                Some(e.name)
                            }
                            _ => None,
                        })
                        .collect();
                    reg.enum_groups.push(EnumGroup {
                        name,
                        kind: enums.kind,
                        values,
                    });
                }
            }
            vk::RegistryChild::Commands(commands) => {
                for c in commands.children {
                    if let Some(c) = convert_command(c) {
                        reg.commands.push(c);
                    }
                }
            }
            vk::RegistryChild::Feature(f) if is_vulkan_api(Some(&f.api)) => {
                let name = internal.get(&f.name).cloned().unwrap_or(f.name);
                let requires =
                    convert_requires(f.children, None, &internal, &mut numbers, &mut aliases);
                // Other blocks it depends on, in public names, less itself.
                let depends: Vec<String> = f
                    .depends
                    .map(|d| publish(&d, &internal))
                    .unwrap_or_default()
                    .split(',')
                    .filter(|d| !d.is_empty() && *d != name)
                    .map(str::to_owned)
                    .collect();
                match reg.features.iter_mut().find(|x| x.name == name) {
                    // A version's internal blocks and its public one become one feature.
                    Some(existing) => {
                        existing.requires.extend(requires);
                        let mut all: Vec<String> = existing
                            .depends
                            .take()
                            .map(|d| d.split(',').map(str::to_owned).collect())
                            .unwrap_or_default();
                        for d in depends {
                            if !all.contains(&d) {
                                all.push(d);
                            }
                        }
                        existing.depends = (!all.is_empty()).then(|| all.join(","));
                    }
                    None => reg.features.push(Interface {
                        name,
                        number: f.number,
                        supported: None,
                        ext_type: None,
                        depends: (!depends.is_empty()).then(|| depends.join(",")),
                        promoted_to: None,
                        requires,
                    }),
                }
            }
            vk::RegistryChild::Formats(formats) => {
                for f in formats.children {
                    reg.formats.push(convert_format(f));
                }
            }
            vk::RegistryChild::Extensions(exts) => {
                for e in exts.children {
                    let depends = e.depends.map(|d| publish(&d, &internal)).or_else(|| {
                        // Registries before 1.3.241 name dependencies in `requires`
                        // and `requiresCore` instead of `depends`.
                        let mut parts: Vec<String> = Vec::new();
                        if let Some(core) = e.requires_core.as_deref() {
                            parts.push(format!("VK_VERSION_{}", core.replace('.', "_")));
                        }
                        if let Some(req) = e.requires.as_deref() {
                            parts.extend(req.split(',').map(str::to_owned));
                        }
                        (!parts.is_empty()).then(|| parts.join("+"))
                    });
                    let requires = convert_requires(
                        e.children,
                        e.number,
                        &internal,
                        &mut numbers,
                        &mut aliases,
                    );
                    reg.extensions.push(Interface {
                        name: e.name,
                        number: e.number.map(|n| n.to_string()),
                        supported: e.supported,
                        ext_type: e.ext_type,
                        depends,
                        promoted_to: e.promotedto,
                        requires,
                    });
                }
            }
            vk::RegistryChild::Sync(s) => sync = Some(s),
            _ => {}
        }
    }
    // Aliases may name values defined later in the file, or other aliases.
    for _ in 0..4 {
        for (name, target) in &aliases {
            if let Some(v) = numbers.get(target).copied() {
                numbers.entry(name.clone()).or_insert(v);
            }
        }
    }
    reg.enum_numbers = numbers;
    reg.version = header_version(&reg.types).ok_or_else(|| Error::BadRegistry {
        path: path.to_owned(),
        message: "no VK_HEADER_VERSION / VK_HEADER_VERSION_COMPLETE define was found".to_owned(),
    })?;
    if reg.commands.is_empty() || !reg.features.iter().any(|f| f.name == "VK_VERSION_1_0") {
        return Err(Error::BadRegistry {
            path: path.to_owned(),
            message: "it defines no commands or no VK_VERSION_1_0 feature".to_owned(),
        });
    }
    check_names(path, &reg)?;
    if let Some(block) = sync {
        reg.sync = Some(super::sync::read(
            block,
            &reg.enum_numbers,
            &reg.version,
            path,
        )?);
    }
    Ok(reg)
}

/// Every name the emitter makes a Rust identifier of must be a C identifier: a file
/// whose `<name>` holds anything else (text moved there from a comment) is broken,
/// and is refused here, naming the element, not deep in the emitter. Include files
/// (`X11/Xlib.h`) are named by path and are exempt; so are `<enums>` groups, whose
/// `API Constants` has a space.
fn check_names(path: &Path, reg: &Registry) -> Result<()> {
    let check = |what: &dyn Fn() -> String, name: &str| {
        let mut chars = name.chars();
        let identifier = chars
            .next()
            .is_some_and(|c| c == '_' || c.is_ascii_alphabetic())
            && chars.all(|c| c == '_' || c.is_ascii_alphanumeric());
        match identifier {
            true => Ok(()),
            false => Err(Error::BadRegistry {
                path: path.to_owned(),
                message: format!("{}: `{name}` is not a C identifier", what()),
            }),
        }
    };
    let fields = |owner: &str, fields: &[Field]| {
        fields.iter().try_for_each(|f| {
            check(&|| format!("a member of `{owner}`"), &f.name)?;
            check(
                &|| format!("the type of `{owner}`'s `{}`", f.name),
                &f.type_name,
            )
        })
    };
    for t in reg
        .types
        .iter()
        .filter(|t| t.category.as_deref() != Some("include"))
    {
        check(&|| "a <type>".to_owned(), &t.name)?;
        fields(&t.name, &t.members)?;
    }
    for g in &reg.enum_groups {
        for v in &g.values {
            check(&|| format!("a value of <enums> `{}`", g.name), v)?;
        }
    }
    for c in &reg.commands {
        check(&|| "a <command>".to_owned(), &c.name)?;
        // An alias is a name and the command it names, nothing more.
        if c.alias.is_none() {
            check(
                &|| format!("the return type of `{}`", c.name),
                &c.return_type,
            )?;
            fields(&c.name, &c.params)?;
        }
    }
    Ok(())
}

/// `1.3.239` from the `VK_HEADER_VERSION` and `VK_HEADER_VERSION_COMPLETE` defines.
fn header_version(types: &[TypeDef]) -> Option<String> {
    let define = |name: &str| {
        types
            .iter()
            .find(|t| t.category.as_deref() == Some("define") && t.name == name)
            .map(|t| t.code.clone())
    };
    let patch: u32 = define("VK_HEADER_VERSION")?
        .split_whitespace()
        .last()?
        .parse()
        .ok()?;
    let complete = define("VK_HEADER_VERSION_COMPLETE")?;
    let args = complete.split_once('(')?.1.split_once(')')?.0;
    let nums: Vec<&str> = args.split(',').map(str::trim).collect();
    let (major, minor) = (
        nums.get(1)?.parse::<u32>().ok()?,
        nums.get(2)?.parse::<u32>().ok()?,
    );
    Some(format!("{major}.{minor}.{patch}"))
}

fn convert_type(t: vk::Type) -> Option<TypeDef> {
    let mut def = TypeDef {
        category: t.category,
        alias: t.alias,
        parent: t.parent,
        returned_only: t.returnedonly.as_deref() == Some("true"),
        struct_extends: t
            .structextends
            .map(|s| s.split(',').map(str::to_owned).collect())
            .unwrap_or_default(),
        allow_duplicate: t.allowduplicate.as_deref() == Some("true"),
        bit_values: t.bitvalues.or(t.requires),
        ..TypeDef::default()
    };
    let mut name = t.name;
    match t.spec {
        vk::TypeSpec::Members(members) => {
            for m in members {
                if let vk::TypeMember::Definition(m) = m {
                    if is_vulkan_api(m.api.as_deref()) {
                        def.members.push(convert_member(m));
                    }
                }
            }
        }
        vk::TypeSpec::Code(code) => {
            for markup in &code.markup {
                if let vk::TypeCodeMarkup::Name(n) = markup {
                    name.get_or_insert_with(|| n.clone());
                }
            }
            def.dispatchable = code.code.contains("VK_DEFINE_HANDLE(");
            def.code = code.code;
        }
        vk::TypeSpec::Funcpointer(fp) => {
            name.get_or_insert_with(|| fp.proto.name.clone());
            def.code = fp.code;
        }
        _ => {}
    }
    def.name = name?;
    Some(def)
}

fn convert_member(m: vk::TypeMemberDefinition) -> Field {
    let mut name = String::new();
    let mut type_name = String::new();
    for markup in &m.markup {
        match markup {
            vk::TypeMemberMarkup::Name(n) if name.is_empty() => name = n.clone(),
            vk::TypeMemberMarkup::Type(t) if type_name.is_empty() => type_name = t.clone(),
            _ => {}
        }
    }
    let shared = SharedAttrs {
        len: m.len,
        altlen: m.altlen,
        optional: m.optional,
        externsync: m.externsync,
        noautovalidity: m.noautovalidity,
    };
    Field {
        selector: m.selector,
        selection: m.selection,
        values: m.values,
        deprecated: m.deprecated,
        ..field(&m.code, type_name, name, shared)
    }
}

/// The attributes struct members and command parameters have in common.
struct SharedAttrs {
    len: Option<String>,
    altlen: Option<String>,
    optional: Option<String>,
    externsync: Option<String>,
    noautovalidity: Option<String>,
}

/// A field from its C declaration, names and shared attributes.
fn field(code: &str, type_name: String, name: String, a: SharedAttrs) -> Field {
    let decl = declaration(code, &type_name, &name);
    Field {
        name,
        type_name,
        len: a.len,
        altlen: a.altlen,
        optional: a.optional,
        externsync: a.externsync,
        noautovalidity: a.noautovalidity.as_deref() == Some("true"),
        ..decl
    }
}

/// The `const`, pointer and array parts of a C declaration such as
/// `const VkFoo* const* ppFoo` or `char name[VK_MAX_NAME_SIZE]`.
fn declaration(code: &str, type_name: &str, name: &str) -> Field {
    let type_at = code.find(type_name).unwrap_or(0);
    let after_type = type_at + type_name.len();
    let name_at = code[after_type.min(code.len())..]
        .find(name)
        .map_or(code.len(), |p| p + after_type);
    let before_name = &code[..name_at];
    let after_name = code[(name_at + name.len()).min(code.len())..].trim();
    // `const` before the type qualifies what the innermost pointer points at; one
    // after a `*` qualifies that pointer, which the next level out points at.
    let (base, stars) = before_name.split_at(after_type.min(before_name.len()));
    let mut inner_first = vec![base.contains("const")];
    for part in stars.split('*').skip(1) {
        inner_first.push(part.contains("const"));
    }
    let pointers = before_name.matches('*').count();
    inner_first.truncate(pointers);
    Field {
        is_const: before_name.contains("const"),
        pointers,
        const_pointees: inner_first.into_iter().rev().collect(),
        static_array: after_name
            .strip_prefix('[')
            .and_then(|rest| rest.split_once(']'))
            .map(|(size, _)| size.trim().to_owned()),
        bitfield: after_name
            .strip_prefix(':')
            .and_then(|width| width.trim().parse().ok()),
        ..Field::default()
    }
}

fn convert_command(c: vk::Command) -> Option<CommandDef> {
    match c {
        vk::Command::Alias { name, alias } => Some(CommandDef {
            name,
            alias: Some(alias),
            ..CommandDef::default()
        }),
        vk::Command::Definition(d) => {
            if !is_vulkan_api(d.api.as_deref()) {
                return None;
            }
            let params = d
                .params
                .into_iter()
                .filter(|p| is_vulkan_api(p.api.as_deref()))
                .map(|p| {
                    let shared = SharedAttrs {
                        len: p.len,
                        altlen: p.altlen,
                        optional: p.optional,
                        externsync: p.externsync,
                        noautovalidity: p.noautovalidity,
                    };
                    let type_name = p.definition.type_name.unwrap_or_default();
                    field(&p.definition.code, type_name, p.definition.name, shared)
                })
                .collect();
            Some(CommandDef {
                name: d.proto.name,
                alias: d.alias,
                return_type: d.proto.type_name.unwrap_or_default(),
                params,
                queues: d.queues,
                renderpass: d.renderpass,
                videocoding: d.videocoding,
                cmdbufferlevel: d.cmdbufferlevel,
                tasks: d.tasks,
                allownoqueues: d.allownoqueues.as_deref() == Some("true"),
                successcodes: d.successcodes,
                errorcodes: d.errorcodes,
            })
        }
        _ => None,
    }
}

/// Records the numeric value of one `<enum>`, or the alias it names. `extnumber` is
/// the number of the enclosing extension, which offsets count from unless the
/// element names its own.
fn note_number(
    numbers: &mut BTreeMap<String, i64>,
    aliases: &mut Vec<(String, String)>,
    e: &vk::Enum,
    extnumber: Option<i64>,
) {
    let value = match &e.spec {
        vk::EnumSpec::Value { value, .. } => parse_c_int(value),
        vk::EnumSpec::Bitpos { bitpos, .. } => {
            (0..64).contains(bitpos).then(|| (1u64 << bitpos) as i64)
        }
        vk::EnumSpec::Offset {
            offset,
            extnumber: own,
            dir,
            ..
        } => own.or(extnumber).and_then(|n| {
            let v = 1_000_000_000i64
                .checked_add(n.checked_sub(1)?.checked_mul(1000)?)?
                .checked_add(*offset)?;
            Some(if *dir { v } else { -v })
        }),
        vk::EnumSpec::Alias { alias, .. } => {
            aliases.push((e.name.clone(), alias.clone()));
            None
        }
        _ => None,
    };
    if let Some(v) = value {
        numbers.insert(e.name.clone(), v);
    }
}

/// A `<format>`: its block, components and planes.
fn convert_format(f: vk::Format) -> crate::registry::FormatDef {
    let mut block_extent = [1, 1, 1];
    if let Some(e) = f.blockExtent.as_deref() {
        for (slot, n) in block_extent.iter_mut().zip(e.split(',')) {
            *slot = n.trim().parse().unwrap_or(1);
        }
    }
    let mut components = Vec::new();
    let mut bits = Vec::new();
    let mut numeric = Vec::new();
    let mut plane_formats = Vec::new();
    for child in f.children {
        match child {
            vk::FormatChild::Component {
                name,
                bits: b,
                numericFormat,
                ..
            } => {
                components.push(name);
                bits.push(b);
                numeric.push(numericFormat);
            }
            vk::FormatChild::Plane { compatible, .. } => plane_formats.push(compatible),
            _ => {}
        }
    }
    crate::registry::FormatDef {
        name: f.name,
        block_size: f.blockSize,
        block_extent,
        components,
        planes: plane_formats.len() as u8,
        plane_formats,
        bits,
        numeric,
        class: f.class,
        chroma: f.chroma,
    }
}

/// An integer literal as vk.xml writes them: `9`, `-1`, `0x7FFFFFFF`; anything else
/// (`(~0U)`, `1000.0F`) is not an enum value and gives `None`.
fn parse_c_int(text: &str) -> Option<i64> {
    let t = text.trim();
    if let Some(hex) = t.strip_prefix("0x").or_else(|| t.strip_prefix("0X")) {
        return i64::from_str_radix(hex, 16).ok();
    }
    t.parse().ok()
}

/// Newer registries (1.4.3xx) split each core version into internal feature blocks
/// (`<feature apitype="internal">`: `VK_BASE_VERSION_1_1`, `VK_COMPUTE_VERSION_1_1`,
/// ...) that the public `VK_VERSION_1_1` depends on. Each internal block's name, and
/// the public version of its number that it belongs to.
fn internal_features(parsed: &vk::Registry) -> BTreeMap<String, String> {
    parsed
        .0
        .iter()
        .filter_map(|child| match child {
            vk::RegistryChild::Feature(f)
                if f.apitype.as_deref() == Some("internal") && is_vulkan_api(Some(&f.api)) =>
            {
                let number = f.number.as_deref()?;
                Some((
                    f.name.clone(),
                    format!("VK_VERSION_{}", number.replace('.', "_")),
                ))
            }
            _ => None,
        })
        .collect()
}

/// A dependency expression with every internal feature block named as the public
/// version it belongs to.
fn publish(expr: &str, internal: &BTreeMap<String, String>) -> String {
    let mut out = String::with_capacity(expr.len());
    let mut word = String::new();
    for c in expr.chars().chain(std::iter::once('\0')) {
        if c.is_ascii_alphanumeric() || c == '_' {
            word.push(c);
            continue;
        }
        out.push_str(internal.get(&word).map_or(word.as_str(), String::as_str));
        word.clear();
        if c != '\0' {
            out.push(c);
        }
    }
    out
}

fn convert_requires(
    children: Vec<vk::ExtensionChild>,
    extnumber: Option<i64>,
    internal: &BTreeMap<String, String>,
    numbers: &mut BTreeMap<String, i64>,
    aliases: &mut Vec<(String, String)>,
) -> Vec<Require> {
    let mut out = Vec::new();
    for child in children {
        if let vk::ExtensionChild::Require {
            api,
            extension,
            feature,
            depends,
            items,
            ..
        } = child
        {
            if !is_vulkan_api(api.as_deref()) {
                continue;
            }
            let depends = depends
                .or_else(|| {
                    let parts: Vec<String> = feature.into_iter().chain(extension).collect();
                    (!parts.is_empty()).then(|| parts.join("+"))
                })
                .map(|d| publish(&d, internal));
            let mut req = Require {
                depends,
                ..Require::default()
            };
            for item in items {
                match item {
                    vk::InterfaceItem::Type { name, .. } => req.types.push(name),
                    vk::InterfaceItem::Command { name, .. } => req.commands.push(name),
                    vk::InterfaceItem::Enum(e) => {
                        if !is_vulkan_api(e.api.as_deref()) {
                            continue;
                        }
                        note_number(numbers, aliases, &e, extnumber);
                        let extends = match &e.spec {
                            vk::EnumSpec::Alias { extends, .. }
                            | vk::EnumSpec::Bitpos { extends, .. }
                            | vk::EnumSpec::Value { extends, .. } => extends.clone(),
                            vk::EnumSpec::Offset { extends, .. } => Some(extends.clone()),
                            _ => None,
                        };
                        if let Some(extends) = extends {
                            req.enum_extensions.push((e.name, extends));
                        }
                    }
                    _ => {}
                }
            }
            out.push(req);
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn reads_bitfield_widths() {
        let f = declaration("uint32_t                 mask:8", "uint32_t", "mask");
        assert_eq!(f.bitfield, Some(8));
        let g = declaration("uint32_t mask", "uint32_t", "mask");
        assert_eq!(g.bitfield, None);
    }

    #[test]
    fn reads_const_pointers_and_arrays() {
        let f = declaration(
            "const VkAllocationCallbacks* pAllocator",
            "VkAllocationCallbacks",
            "pAllocator",
        );
        assert!(f.is_const);
        assert_eq!(f.pointers, 1);
        assert_eq!(f.const_pointees, [true]);
        let f = declaration(
            "const VkAccelerationStructureBuildRangeInfoKHR* const* ppBuildRangeInfos",
            "VkAccelerationStructureBuildRangeInfoKHR",
            "ppBuildRangeInfos",
        );
        assert_eq!(f.const_pointees, [true, true]);
        let f = declaration("void** ppData", "void", "ppData");
        assert_eq!(f.const_pointees, [false, false]);
        let f = declaration(
            "struct AHardwareBuffer** pBuffer",
            "AHardwareBuffer",
            "pBuffer",
        );
        assert_eq!(f.const_pointees, [false, false]);
        let f = declaration("void** ppData", "void", "ppData");
        assert!(!f.is_const);
        assert_eq!(f.pointers, 2);
        let f = declaration(
            "char deviceName[VK_MAX_PHYSICAL_DEVICE_NAME_SIZE]",
            "char",
            "deviceName",
        );
        assert_eq!(
            f.static_array.as_deref(),
            Some("VK_MAX_PHYSICAL_DEVICE_NAME_SIZE")
        );
        let f = declaration("const float blendConstants[4]", "float", "blendConstants");
        assert_eq!(f.static_array.as_deref(), Some("4"));
        assert!(f.is_const);
        assert_eq!(f.pointers, 0);
    }

    #[test]
    fn internal_blocks_are_named_as_their_public_version() {
        let internal: std::collections::BTreeMap<String, String> = [
            ("VK_BASE_VERSION_1_1", "VK_VERSION_1_1"),
            ("VK_GRAPHICS_VERSION_1_2", "VK_VERSION_1_2"),
        ]
        .into_iter()
        .map(|(a, b)| (a.to_owned(), b.to_owned()))
        .collect();
        assert_eq!(
            super::publish(
                "(VK_KHR_a+VK_BASE_VERSION_1_1),VK_GRAPHICS_VERSION_1_2",
                &internal
            ),
            "(VK_KHR_a+VK_VERSION_1_1),VK_VERSION_1_2"
        );
        assert_eq!(
            super::publish("VK_BASE_VERSION_1_10", &internal),
            "VK_BASE_VERSION_1_10"
        );
        assert_eq!(super::publish("", &internal), "");
    }
}
