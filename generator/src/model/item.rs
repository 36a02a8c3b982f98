//! The model's own commands, types and fields: what the registry pass read, with
//! every attribute that later passes reason about parsed once here (`len`,
//! `optional`, `externsync`), so no pass re-reads attribute text.

use super::attrs::{self, ExternSync, LenEntry};
use crate::registry;

/// A struct member or a command parameter.
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
    /// `len`, as written (the implicit-rule derivation follows the text, as the
    /// specification's toolchain does).
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
    /// The attributes, parsed.
    pub parsed: Parsed,
}

/// The attributes of a field that later passes reason about, parsed once.
#[derive(Debug, Clone, Default, PartialEq, Eq, serde::Serialize)]
pub struct Parsed {
    /// `len`, one entry per pointer level.
    pub len: Vec<LenEntry>,
    /// `optional`, one flag per level.
    pub optional: Vec<bool>,
    /// `externsync`.
    pub externsync: Vec<ExternSync>,
}

impl Field {
    /// Whether the outermost level is optional.
    pub fn is_optional(&self) -> bool {
        self.parsed.optional.first().copied().unwrap_or(false)
    }
}

impl From<&registry::Field> for Field {
    fn from(f: &registry::Field) -> Field {
        let registry::Field {
            name,
            type_name,
            is_const,
            pointers,
            const_pointees,
            static_array,
            len,
            altlen,
            optional,
            externsync,
            noautovalidity,
            selector,
            selection,
            values,
            deprecated,
            bitfield,
        } = f.clone();
        let parsed = Parsed {
            len: len.as_deref().map(attrs::parse_len).unwrap_or_default(),
            optional: attrs::parse_optional(optional.as_deref()),
            externsync: externsync
                .as_deref()
                .map(attrs::parse_externsync)
                .unwrap_or_default(),
        };
        Field {
            name,
            type_name,
            is_const,
            pointers,
            const_pointees,
            static_array,
            len,
            altlen,
            optional,
            externsync,
            noautovalidity,
            selector,
            selection,
            values,
            deprecated,
            bitfield,
            parsed,
        }
    }
}

/// A command.
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
    /// `allownoqueues="true"`: callable on a device created with no queues.
    pub allownoqueues: bool,
    /// `successcodes`, as written.
    pub successcodes: Option<String>,
    /// `errorcodes`, as written.
    pub errorcodes: Option<String>,
}

impl From<&registry::CommandDef> for CommandDef {
    fn from(c: &registry::CommandDef) -> CommandDef {
        CommandDef {
            name: c.name.clone(),
            alias: c.alias.clone(),
            return_type: c.return_type.clone(),
            params: c.params.iter().map(Field::from).collect(),
            queues: c.queues.clone(),
            renderpass: c.renderpass.clone(),
            videocoding: c.videocoding.clone(),
            cmdbufferlevel: c.cmdbufferlevel.clone(),
            tasks: c.tasks.clone(),
            allownoqueues: c.allownoqueues,
            successcodes: c.successcodes.clone(),
            errorcodes: c.errorcodes.clone(),
        }
    }
}

/// What kind of type a registry type is: its `category`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Kind {
    /// `struct`.
    Struct,
    /// `union`.
    Union,
    /// `handle`.
    Handle,
    /// `enum`.
    Enum,
    /// `bitmask`.
    Bitmask,
    /// `basetype`.
    Basetype,
    /// `funcpointer`.
    Funcpointer,
    /// `define`.
    Define,
    /// `include`.
    Include,
    /// A category this generator does not know; no pass gives it a meaning.
    Other,
}

impl Kind {
    /// The kind a `category` attribute names.
    pub fn parse(category: &str) -> Kind {
        match category {
            "struct" => Kind::Struct,
            "union" => Kind::Union,
            "handle" => Kind::Handle,
            "enum" => Kind::Enum,
            "bitmask" => Kind::Bitmask,
            "basetype" => Kind::Basetype,
            "funcpointer" => Kind::Funcpointer,
            "define" => Kind::Define,
            "include" => Kind::Include,
            _ => Kind::Other,
        }
    }

    /// The `category` attribute of the kind, as the registry writes it (`other` for
    /// one this generator does not know).
    pub fn name(self) -> &'static str {
        match self {
            Kind::Struct => "struct",
            Kind::Union => "union",
            Kind::Handle => "handle",
            Kind::Enum => "enum",
            Kind::Bitmask => "bitmask",
            Kind::Basetype => "basetype",
            Kind::Funcpointer => "funcpointer",
            Kind::Define => "define",
            Kind::Include => "include",
            Kind::Other => "other",
        }
    }
}

/// A type.
#[derive(Debug, Clone, Default)]
pub struct TypeDef {
    /// The type's name.
    pub name: String,
    /// `category`; none for the C types the registry names (`uint32_t`).
    pub category: Option<Kind>,
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

impl From<&registry::TypeDef> for TypeDef {
    fn from(t: &registry::TypeDef) -> TypeDef {
        TypeDef {
            name: t.name.clone(),
            category: t.category.as_deref().map(Kind::parse),
            alias: t.alias.clone(),
            parent: t.parent.clone(),
            dispatchable: t.dispatchable,
            returned_only: t.returned_only,
            struct_extends: t.struct_extends.clone(),
            allow_duplicate: t.allow_duplicate,
            bit_values: t.bit_values.clone(),
            members: t.members.iter().map(Field::from).collect(),
            code: t.code.clone(),
        }
    }
}
