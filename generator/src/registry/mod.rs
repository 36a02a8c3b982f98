//! Registry pass: read `vk.xml` and `validusage.json` into plain Rust data.
//!
//! Nothing after this pass touches XML or JSON. The data here is the registry as
//! written, for the `vulkan` API only (items marked `api="vulkansc"` are dropped), with
//! no resolution of aliases or requirements: that is the model pass's job.

mod convert;
mod sync;
mod validusage;
mod wellformed;

pub use sync::{SyncItem, SyncPipeline, SyncTables};
pub use validusage::{load_validusage, parse_validusage, ValidUsage, VuEntry};

use crate::error::{Error, Result};
use std::path::Path;

/// The parts of `vk.xml` the generator uses.
#[derive(Debug, Clone, Default)]
pub struct Registry {
    /// `VK_HEADER_VERSION_COMPLETE` as `major.minor.patch`, e.g. `1.3.239`.
    pub version: String,
    /// Every `<type>` of the vulkan API, in file order.
    pub types: Vec<TypeDef>,
    /// Every `<enums>` group with the values written inside it (not those that
    /// features and extensions add).
    pub enum_groups: Vec<EnumGroup>,
    /// Every `<command>` of the vulkan API.
    pub commands: Vec<CommandDef>,
    /// The `<feature>` blocks of the vulkan API (`VK_VERSION_1_0`, ...).
    pub features: Vec<Interface>,
    /// The `<extension>` blocks, all of them (check `supported`).
    pub extensions: Vec<Interface>,
    /// The numeric value of every enum value name the file defines, aliases resolved
    /// (`VK_FORMAT_R8_UNORM` is 9; extension values from their offset and number).
    pub enum_numbers: std::collections::BTreeMap<String, i64>,
    /// Every `<format>` of the `<formats>` block: what a `VkFormat` is made of.
    pub formats: Vec<FormatDef>,
    /// The `<sync>` block, where the registry has one (1.3.2xx on).
    pub sync: Option<SyncTables>,
}

/// One `<format>` element.
#[derive(Debug, Clone, Default, PartialEq, Eq)]
pub struct FormatDef {
    /// `VK_FORMAT_...`.
    pub name: String,
    /// Bytes per texel block.
    pub block_size: u8,
    /// Texel block width, height and depth (`1, 1, 1` unless `blockExtent` says).
    pub block_extent: [u32; 3],
    /// The components' names in order (`R`, `G`, `B`, `A`, `D`, `S`).
    pub components: Vec<String>,
    /// How many planes (0 for a format that is not multi-planar).
    pub planes: u8,
    /// Each plane's compatible single-plane format, in plane order.
    pub plane_formats: Vec<String>,
    /// Each component's bit width as written (`8`, `24`, `compressed`), in order.
    pub bits: Vec<String>,
    /// Each component's `numericFormat` (`UNORM`, `UINT`, `SFLOAT`, ...), in order.
    pub numeric: Vec<String>,
    /// `class`: formats of one class are compatible (views, copies).
    pub class: String,
    /// `chroma` (`420`, `422`, `444`): the format needs a sampler Y'CbCr conversion.
    pub chroma: Option<String>,
}

/// One `<type>` element.
#[derive(Debug, Clone, Default)]
pub struct TypeDef {
    /// The type's name.
    pub name: String,
    /// `category` (`struct`, `union`, `handle`, `enum`, `bitmask`, `basetype`, ...).
    pub category: Option<String>,
    /// The type this one is another name for.
    pub alias: Option<String>,
    /// For handles: the `parent` attribute, as written (may list several).
    pub parent: Option<String>,
    /// For handles: declared with `VK_DEFINE_HANDLE` (dispatchable).
    pub dispatchable: bool,
    /// For structs: `returnedonly="true"`.
    pub returned_only: bool,
    /// For structs: the structs whose `pNext` chain this one may extend.
    pub struct_extends: Vec<String>,
    /// For structs: `allowduplicate="true"`.
    pub allow_duplicate: bool,
    /// For bitmasks: the `requires`/`bitvalues` attribute naming the FlagBits enum.
    pub bit_values: Option<String>,
    /// For structs and unions: the members, in order.
    pub members: Vec<Field>,
    /// For `define`s: the C text, used to read `VK_HEADER_VERSION`.
    pub code: String,
}

/// A struct member or a command parameter, with its attributes as written.
#[derive(Debug, Clone, Default, PartialEq, Eq)]
pub struct Field {
    /// The member or parameter name.
    pub name: String,
    /// The base type name (`uint32_t`, `VkBuffer`, `void`, ...).
    pub type_name: String,
    /// `const` appears in the declaration.
    pub is_const: bool,
    /// Number of `*` in the declaration.
    pub pointers: usize,
    /// For each pointer level, outermost first: whether what it points at is
    /// `const` (`const VkFoo* const* p`: both; `void** p`: neither).
    pub const_pointees: Vec<bool>,
    /// For fixed-size arrays: the size between the brackets.
    pub static_array: Option<String>,
    /// `len`, as written.
    pub len: Option<String>,
    /// `altlen`, as written.
    pub altlen: Option<String>,
    /// `optional`, as written.
    pub optional: Option<String>,
    /// `externsync`, as written.
    pub externsync: Option<String>,
    /// `noautovalidity="true"`.
    pub noautovalidity: bool,
    /// `selector` (on a union-typed member: the member that selects).
    pub selector: Option<String>,
    /// `selection` (on a union member: the selector values that choose it).
    pub selection: Option<String>,
    /// `values` (on `sType`: the structure type value).
    pub values: Option<String>,
    /// `deprecated`, as written.
    pub deprecated: Option<String>,
    /// For a C bitfield (`uint32_t mask:8`): its width in bits.
    pub bitfield: Option<u32>,
}

/// One `<enums>` group.
#[derive(Debug, Clone, Default)]
pub struct EnumGroup {
    /// The group's name (`VkBufferCreateFlagBits`, ...).
    pub name: String,
    /// `type`: `enum`, `bitmask` or `constants`.
    pub kind: Option<String>,
    /// The values written inside the group.
    pub values: Vec<String>,
}

/// One `<command>` element.
#[derive(Debug, Clone, Default)]
pub struct CommandDef {
    /// The command's name.
    pub name: String,
    /// For an alias: the command it is another name for.
    pub alias: Option<String>,
    /// The return type.
    pub return_type: String,
    /// The parameters, in order.
    pub params: Vec<Field>,
    /// `queues`, as written.
    pub queues: Option<String>,
    /// `renderpass`: `inside`, `outside` or `both`.
    pub renderpass: Option<String>,
    /// `videocoding`: `inside`, `outside` or `both`.
    pub videocoding: Option<String>,
    /// `cmdbufferlevel`, as written.
    pub cmdbufferlevel: Option<String>,
    /// `tasks`, as written.
    pub tasks: Option<String>,
    /// `allownoqueues="true"`: the command may be called on a device created with no
    /// queues (newer registries).
    pub allownoqueues: bool,
    /// `successcodes`, as written.
    pub successcodes: Option<String>,
    /// `errorcodes`, as written.
    pub errorcodes: Option<String>,
}

/// A `<feature>` or `<extension>`: what it is and what it requires.
#[derive(Debug, Clone, Default)]
pub struct Interface {
    /// `VK_VERSION_1_2` or `VK_KHR_swapchain`.
    pub name: String,
    /// For features: `1.2`. For extensions: the extension number.
    pub number: Option<String>,
    /// For extensions: `supported` (`vulkan`, `vulkansc`, `disabled`, ...).
    pub supported: Option<String>,
    /// For extensions: `type`, `instance` or `device`.
    pub ext_type: Option<String>,
    /// For extensions: what it depends on, in vk.xml's expression syntax.
    pub depends: Option<String>,
    /// For extensions: `promotedto`, the core version (or extension) that took its
    /// functionality in.
    pub promoted_to: Option<String>,
    /// Its `<require>` blocks for the vulkan API.
    pub requires: Vec<Require>,
}

/// One `<require>` block.
#[derive(Debug, Clone, Default)]
pub struct Require {
    /// The extra condition of the block (`depends`, or the older `feature` and
    /// `extension` attributes joined with `+`).
    pub depends: Option<String>,
    /// Types it requires.
    pub types: Vec<String>,
    /// Commands it requires.
    pub commands: Vec<String>,
    /// Enum values it adds to a group: (value name, group it extends).
    pub enum_extensions: Vec<(String, String)>,
}

/// True when an `api` attribute (absent, or a comma list) includes `vulkan`.
pub(crate) fn is_vulkan_api(api: Option<&str>) -> bool {
    api.is_none_or(|a| a.split(',').any(|x| x.trim() == "vulkan"))
}

/// Read and convert `vk.xml`. The file is first checked for well-formedness so that
/// a broken file is reported with its line and column.
pub fn load_registry(path: &Path) -> Result<Registry> {
    let bytes = std::fs::read(path).map_err(|source| Error::Read {
        path: path.to_owned(),
        source,
    })?;
    parse_registry(path, &bytes)
}

/// Convert the text of a `vk.xml` already read; `path` names it in errors. Any bytes
/// give a registry or an error, never a panic (`fuzz/`'s `registry` target).
pub fn parse_registry(path: &Path, bytes: &[u8]) -> Result<Registry> {
    wellformed::check(path, bytes)?;
    let (parsed, recoverable) = vk_parse::parse_stream(bytes).map_err(|e| Error::BadRegistry {
        path: path.to_owned(),
        message: match e {
            vk_parse::FatalError::MissingRegistryElement => {
                "the root element is not <registry>".to_owned()
            }
            other => format!("{other:?}"),
        },
    })?;
    // Elements and attributes vk-parse does not know are schema additions of newer
    // registries and are skipped; missing or malformed parts mean the file is broken.
    if let Some(e) = recoverable.iter().find(|e| {
        !matches!(
            e,
            vk_parse::Error::UnexpectedElement { .. } | vk_parse::Error::UnexpectedAttribute { .. }
        )
    }) {
        return Err(Error::BadRegistry {
            path: path.to_owned(),
            message: describe_parse_error(e),
        });
    }
    convert::convert(path, parsed)
}

fn describe_parse_error(e: &vk_parse::Error) -> String {
    match e {
        vk_parse::Error::MissingElement { xpath, name } => {
            format!("{xpath} lacks its <{name}> element")
        }
        vk_parse::Error::MissingAttribute { xpath, name } => {
            format!("{xpath} lacks its `{name}` attribute")
        }
        vk_parse::Error::UnexpectedAttributeValue { xpath, name, value } => {
            format!("{xpath}: `{name}` has the unexpected value `{value}`")
        }
        vk_parse::Error::SchemaViolation { xpath, desc } => format!("{xpath}: {desc}"),
        vk_parse::Error::ParseIntError { xpath, text, .. } => {
            format!("{xpath}: `{text}` is not a number")
        }
        other => format!("{other:?}"),
    }
}
