//! The shape of every struct member: how a safe counterpart exposes it. Emitters and
//! the settlement records both read these shapes, so what the code does and what the
//! report claims come from one decision.

use super::types::TypeFacts;
use crate::model::Field;
use crate::model::Kind;
use crate::model::{LenEntry, Model};

/// How a member of a safe struct is set.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Member {
    /// `sType`: fixed by the constructor.
    SType,
    /// `pNext`: only structs that extend this one can be pushed.
    PNext,
    /// A count that a slice setter fills in.
    Count,
    /// A value of a plain type (scalar, enum, flags, plain struct or union).
    Value,
    /// A fixed-size array of a plain type.
    Array(String),
    /// A handle, taken as a wrapper.
    Handle {
        /// May be null.
        optional: bool,
    },
    /// An array of handles, taken as `impl Handles` (a wrapper or a `HandleSlice`).
    HandleSlice {
        /// The member that holds the length.
        count: String,
    },
    /// A struct held by value that has a safe counterpart: taken as that counterpart
    /// in the constructor, since a zeroed one would break the counterpart's invariants.
    Nested,
    /// A pointer to one struct that Vulkan writes, taken as a mutable borrow (of its
    /// safe counterpart where it has one) for as long as the struct lives.
    StructMut {
        /// May be null.
        optional: bool,
    },
    /// A pointer to one struct, taken as a reference to its safe counterpart.
    StructRef {
        /// May be null.
        optional: bool,
    },
    /// An array of structs (safe counterparts or plain ash structs), or of scalars.
    Slice {
        /// The member that holds the length.
        count: String,
        /// The elements are safe counterparts.
        safe: bool,
    },
    /// Bytes: a `void*` sized in bytes by `count`.
    Bytes {
        /// The member that holds the size.
        count: String,
    },
    /// SPIR-V code: a `uint32_t*` sized in bytes by `count` (`codeSize / 4`).
    Code {
        /// The member that holds the size in bytes.
        count: String,
    },
    /// A C string.
    CStr {
        /// May be null.
        optional: bool,
    },
    /// An array of C strings.
    CStrSlice {
        /// The member that holds the length.
        count: String,
    },
    /// A pointer to a video codec's own structs (video.xml's `StdVideo*`, in ash's
    /// `vk::native`): one, or `count` of them. Taken as a reference or a slice, so
    /// the pointer and its length are valid; the setter is `unsafe`, as some of
    /// those structs hold pointers of their own (an SPS's scaling lists and VUI),
    /// which Vulkan follows.
    CodecStd {
        /// The member that holds the length, for an array.
        count: Option<String>,
    },
    /// A union that another member selects the meaning of (`VkDescriptorGetInfoEXT`'s
    /// `data`, chosen by `type`): taken, with the selector, as one variant of a safe
    /// enum of the union's members, which the constructor requires.
    Selected {
        /// The union's members, each with the selector values that choose it.
        variants: Vec<Variant>,
        /// The member that selects.
        selector: String,
    },
    /// The member that selects a union's meaning: set only by the union's variant.
    Selector,
    /// A pointer to an array whose length is a product of constants (`pVersionData`,
    /// `2*VK_UUID_SIZE` bytes): taken as a reference to an array of that size.
    FixedRef {
        /// The registry's C expression of the length.
        size: String,
    },
    /// Opaque user data handed back to a callback; never dereferenced by Vulkan.
    UserData,
    /// Bytes Vulkan reads, of a size no member gives (capture data, a driver's
    /// private data): a byte slice through an `unsafe` setter, whose caller
    /// vouches for the contents and their size.
    OpaqueBytes,
    /// A pointer to a window-system object: set through an `unsafe` setter.
    Platform,
    /// A window-system value (an X11 `Window`, an `xcb_window_t`): set through an
    /// `unsafe` setter, since Vulkan cannot tell a live window from a number.
    PlatformValue,
    /// Not exposed; the text says why.
    Unsupported(String),
}

/// One member of a selected union, as the safe enum's variant takes it.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Variant {
    /// The union member.
    pub member: Field,
    /// The selector value that chooses it (one variant per value).
    pub selection: String,
    /// How the variant holds it.
    pub kind: VariantKind,
}

/// What a variant of a selected union holds.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum VariantKind {
    /// A pointer to one handle: a wrapper.
    Handle {
        /// May be null.
        optional: bool,
    },
    /// A pointer to one struct: a reference to it (its safe counterpart if it has one).
    StructRef {
        /// May be null.
        optional: bool,
        /// The struct has a safe counterpart.
        safe: bool,
    },
    /// A struct with a safe counterpart, by value.
    Nested,
    /// A plain value (a number, a device address, a plain struct).
    Value,
}

/// The variants of a selected union, or why the union cannot be taken safely.
fn union_variants(model: &Model, facts: &TypeFacts, union: &str) -> Result<Vec<Variant>, String> {
    let t = model.types.get(union).ok_or("an unknown union")?;
    let mut out = Vec::new();
    for u in &t.members {
        let selection = u
            .selection
            .as_deref()
            .ok_or("a union member no value selects")?;
        let category = model.category(&u.type_name);
        let optional = u.is_optional();
        let kind = match (u.pointers, category) {
            (1, Some(Kind::Handle)) if u.is_const && u.len.is_none() => {
                VariantKind::Handle { optional }
            }
            (1, Some(Kind::Struct)) if u.is_const && u.len.is_none() => VariantKind::StructRef {
                optional,
                safe: facts.is_safe(&u.type_name),
            },
            (0, Some(Kind::Struct)) if facts.is_safe(&u.type_name) => VariantKind::Nested,
            (0, Some(Kind::Struct)) if !facts.has_lifetime(&u.type_name) => VariantKind::Value,
            (0, _)
                if u.static_array.is_none()
                    && (is_c_scalar(&u.type_name) || matches!(category, Some(Kind::Basetype))) =>
            {
                VariantKind::Value
            }
            _ => return Err(format!("a union member `{}` of no safe shape", u.name)),
        };
        for value in selection.split(',') {
            out.push(Variant {
                member: u.clone(),
                selection: value.to_owned(),
                kind,
            });
        }
    }
    Ok(out)
}

/// The shapes of a struct's members, in order.
pub fn struct_members(model: &Model, facts: &TypeFacts, name: &str) -> Vec<(Field, Member)> {
    let Some(t) = model.types.get(name) else {
        return Vec::new();
    };
    // A count is set only by its array's setter when some array it sizes is
    // required; a count of optional arrays (descriptorCount beside
    // pImmutableSamplers) also means something alone, so it keeps its own setter.
    let counts: Vec<String> = t
        .members
        .iter()
        .filter(|m| {
            !crate::model::attrs::parse_optional(m.optional.as_deref())
                .first()
                .copied()
                .unwrap_or(false)
        })
        .filter_map(|m| m.len.as_deref())
        .flat_map(|len| crate::model::attrs::parse_len(len).into_iter().take(1))
        .filter_map(|e| match e {
            LenEntry::Reference(parts) if parts.len() == 1 => Some(parts[0].clone()),
            LenEntry::Math(m) => math_count(&m),
            _ => None,
        })
        .collect();
    t.members
        .iter()
        .map(|m| {
            let shape = match member_shape(model, facts, &t.name, m, &counts, &t.members) {
                Member::Handle { .. } if super::special::nullable(name, &m.name) => {
                    Member::Handle { optional: true }
                }
                // Only a safe struct's constructor can require the union's variant; a
                // plain struct (data the device reads) keeps both as ash has them.
                Member::Selected { .. } if !facts.is_safe(name) => {
                    Member::Unsupported("a union chosen by another member".into())
                }
                Member::Selector if !facts.is_safe(name) => Member::Value,
                shape => shape,
            };
            (m.clone(), shape)
        })
        .collect()
}

/// `\textrm{codeSize} \over 4` names `codeSize`.
fn math_count(math: &str) -> Option<String> {
    let start = math.find("\\textrm{")? + "\\textrm{".len();
    let end = math[start..].find('}')? + start;
    math.contains("\\over 4")
        .then(|| math[start..end].to_owned())
}

/// `void*` members that point to a window-system object rather than to bytes:
/// MoltenVK's view (an `NSView` or `CAMetalLayer`).
const WINDOW_OBJECT_MEMBERS: &[(&str, &str)] = &[
    ("VkMacOSSurfaceCreateInfoMVK", "pView"),
    ("VkIOSSurfaceCreateInfoMVK", "pView"),
];

fn member_shape(
    model: &Model,
    facts: &TypeFacts,
    owner: &str,
    m: &Field,
    counts: &[String],
    members: &[Field],
) -> Member {
    let category = model.category(&m.type_name);
    let p = &m.parsed;
    let optional = m.is_optional();
    if m.name == "sType" && m.values.is_some() {
        return Member::SType;
    }
    if m.name == "pNext" {
        return Member::PNext;
    }
    if m.deprecated.is_some()
        || (m.name == "ppEnabledLayerNames"
            && members.iter().any(|x| x.name == "pQueueCreateInfos"))
    {
        return Member::Unsupported("deprecated by the specification".into());
    }
    if counts.contains(&m.name) && m.pointers == 0 {
        // Only counts of supported arrays are filled in by setters; a count whose
        // array is unsupported stays zero, which every array allows when empty.
        return Member::Count;
    }
    if m.type_name != "void" && super::types::ash_type(model, facts, &m.type_name).is_none() {
        return Member::Unsupported(format!("ash has no type `{}`", m.type_name));
    }
    if let Some(selector) = &m.selector {
        return match union_variants(model, facts, &m.type_name) {
            Ok(variants) => Member::Selected {
                variants,
                selector: selector.clone(),
            },
            Err(why) => {
                Member::Unsupported(format!("a union chosen by another member, with {why}"))
            }
        };
    }
    if members.iter().any(|x| {
        x.selector.as_deref() == Some(m.name.as_str())
            && union_variants(model, facts, &x.type_name).is_ok()
    }) {
        return Member::Selector;
    }
    if m.bitfield.is_some() {
        return Member::Unsupported("a C bitfield, which ash packs with its neighbours".into());
    }
    let first_len = p.len.first().cloned();
    let count_of = |e: &Option<LenEntry>| -> Option<String> {
        match e {
            Some(LenEntry::Reference(parts)) if parts.len() == 1 => members
                .iter()
                .any(|x| x.name == parts[0])
                .then(|| parts[0].clone()),
            _ => None,
        }
    };
    if m.pointers == 0 {
        if let Some(size) = &m.static_array {
            if category == Some(Kind::Handle) || facts.is_safe(&m.type_name) {
                return Member::Unsupported("a fixed array of handles or structs".into());
            }
            return Member::Array(size.clone());
        }
        return match category {
            Some(Kind::Handle) => Member::Handle { optional },
            Some(Kind::Struct) if facts.is_safe(&m.type_name) => Member::Nested,
            Some(Kind::Union) if !facts.union_is_plain(model, &m.type_name) => {
                Member::Unsupported("a union that carries pointers or handles".into())
            }
            _ if m.type_name == "VkBool32" || category.is_some() || is_c_scalar(&m.type_name) => {
                Member::Value
            }
            None if m.type_name != "void" && model.types.contains_key(&m.type_name) => {
                Member::PlatformValue
            }
            _ => Member::Unsupported(format!("type `{}`", m.type_name)),
        };
    }
    if m.name == "pUserData" && m.type_name == "void" {
        return Member::UserData;
    }
    // (`VkVideoDecodeH265PictureInfoKHR::pStdPictureInfo` lacks its `const` in
    // 1.3.239; Vulkan reads it, and later registries have the `const`.)
    if category.is_none() && m.pointers == 1 && super::types::is_codec_std(model, &m.type_name) {
        return match (&first_len, count_of(&first_len)) {
            (None, _) => Member::CodecStd { count: None },
            (Some(_), Some(count)) => Member::CodecStd { count: Some(count) },
            (Some(_), None) => Member::Unsupported(
                "a pointer whose length the registry gives as an expression".into(),
            ),
        };
    }
    // A `void*` that names a window-system object (MoltenVK's `NSView`), not bytes.
    let object = WINDOW_OBJECT_MEMBERS.contains(&(owner, m.name.as_str()));
    if category.is_none() && !is_c_scalar(&m.type_name) && (m.type_name != "void" || object) {
        return Member::Platform;
    }
    if !m.is_const {
        // One struct Vulkan writes (a render pass's creation feedback): a mutable
        // borrow, required by the constructor where the pointer is.
        if m.pointers == 1 && first_len.is_none() && category == Some(Kind::Struct) {
            return Member::StructMut { optional };
        }
        return Member::Unsupported("a pointer Vulkan writes through".into());
    }
    if m.pointers == 1 {
        if m.type_name == "char" && matches!(first_len, Some(LenEntry::NullTerminated)) {
            return Member::CStr { optional };
        }
        if let Some(Some(count)) = first_len.as_ref().map(|e| match e {
            LenEntry::Math(math) if m.type_name == "uint32_t" => math_count(math),
            _ => None,
        }) {
            return Member::Code { count };
        }
        if let Some(count) = count_of(&first_len) {
            return match category {
                Some(Kind::Handle) => Member::HandleSlice { count },
                _ if m.type_name == "void" => Member::Bytes { count },
                Some(Kind::Struct) => Member::Slice {
                    count,
                    safe: facts.is_safe(&m.type_name),
                },
                Some(Kind::Union) if facts.union_is_plain(model, &m.type_name) => {
                    Member::Slice { count, safe: false }
                }
                _ if category.is_some() || is_c_scalar(&m.type_name) => {
                    Member::Slice { count, safe: false }
                }
                _ => Member::Unsupported(format!("an array of `{}`", m.type_name)),
            };
        }
        if first_len.is_none() && category == Some(Kind::Struct) {
            return Member::StructRef { optional };
        }
        // A length of constants only (`2*VK_UUID_SIZE`): an array of that size.
        if let Some(size) = m.altlen.as_deref().filter(|a| constant_size(a).is_some()) {
            if is_c_scalar(&m.type_name) {
                return Member::FixedRef {
                    size: size.to_owned(),
                };
            }
        }
        if first_len.is_none() && m.type_name == "void" && m.is_const {
            return Member::OpaqueBytes;
        }
        return Member::Unsupported(
            "a pointer whose length the registry gives as an expression".into(),
        );
    }
    if m.pointers == 2 && m.type_name == "char" {
        if let Some(count) = count_of(&first_len) {
            return Member::CStrSlice { count };
        }
    }
    Member::Unsupported("a pointer to pointers".into())
}

/// A window-system type that the registry passes by value somewhere (a Win32
/// `HANDLE`, a Zircon `zx_handle_t`, an X11 `Window`): a plain number or pointer,
/// as opposed to an object only ever pointed to (an Xlib `Display`).
pub fn is_foreign_value(model: &Model, name: &str) -> bool {
    let foreign = model
        .types
        .get(name)
        .is_some_and(|t| t.category.is_none() && !super::types::is_codec_std(model, name));
    foreign
        && !is_c_scalar(name)
        && name != "void"
        && (model.types.values().any(|t| {
            t.members
                .iter()
                .any(|m| m.type_name == name && m.pointers == 0)
        }) || model.commands.values().any(|c| {
            c.params
                .iter()
                .any(|p| p.type_name == name && p.pointers == 0)
        }))
}

/// The factors of a length that is a product of numbers and API constants
/// (`2*VK_UUID_SIZE`), or `None` when it names anything else.
pub fn constant_size(expr: &str) -> Option<Vec<&str>> {
    let factors: Vec<&str> = expr.split('*').map(str::trim).collect();
    factors
        .iter()
        .all(|f| {
            !f.is_empty()
                && (f.chars().all(|c| c.is_ascii_digit())
                    || (f.starts_with("VK_")
                        && f.chars()
                            .all(|c| c.is_ascii_uppercase() || c.is_ascii_digit() || c == '_')))
        })
        .then_some(factors)
}

/// C scalar types.
pub fn is_c_scalar(name: &str) -> bool {
    matches!(
        name,
        "float"
            | "double"
            | "uint8_t"
            | "uint16_t"
            | "uint32_t"
            | "uint64_t"
            | "int8_t"
            | "int16_t"
            | "int32_t"
            | "int64_t"
            | "size_t"
            | "int"
            | "char"
    )
}

/// The arrays of a struct that share one count member, and how their setters keep
/// the count equal to the length of every array that is set.
///
/// A count read by several arrays is where a builder goes wrong: a setter per array
/// that each writes the count lets the last one win, and Vulkan then reads past the
/// shorter array. The roles below make a disagreeing struct unbuildable.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct CountGroup {
    /// The member that holds the length.
    pub count: String,
    /// Required arrays: set together by one setter, named after the first, that
    /// refuses slices of different lengths.
    pub leads: Vec<String>,
    /// Optional arrays beside leads: their setter refuses a length other than the
    /// count the leads set, and a lead setter of another length clears them.
    pub followers: Vec<String>,
    /// Arrays of which Vulkan reads at most one, or that are all optional with no
    /// lead: each setter writes the count and clears the others of another length.
    pub alternatives: Vec<String>,
    /// The count has its own setter too (it means something without any array);
    /// that setter clears the arrays of another length.
    pub count_setter: bool,
}

impl CountGroup {
    /// Whether a member is one of this group's arrays.
    pub fn holds(&self, member: &str) -> bool {
        self.leads
            .iter()
            .chain(&self.followers)
            .chain(&self.alternatives)
            .any(|m| m == member)
    }

    /// The group's arrays other than `member`.
    pub fn others<'s>(&'s self, member: &'s str) -> impl Iterator<Item = &'s String> + 's {
        self.leads
            .iter()
            .chain(&self.followers)
            .chain(&self.alternatives)
            .filter(move |m| *m != member)
    }
}

/// The count groups of a struct whose count more than one setter writes.
pub fn count_groups(members: &[(Field, Member)]) -> Vec<CountGroup> {
    let mut groups: Vec<CountGroup> = Vec::new();
    for (m, shape) in members {
        let count = match shape {
            Member::HandleSlice { count }
            | Member::Slice { count, .. }
            | Member::Bytes { count }
            | Member::CStrSlice { count }
            | Member::CodecStd { count: Some(count) } => count,
            _ => continue,
        };
        let i = match groups.iter().position(|g| &g.count == count) {
            Some(i) => i,
            None => {
                let count_setter = members
                    .iter()
                    .any(|(f, s)| &f.name == count && *s == Member::Value);
                groups.push(CountGroup {
                    count: count.clone(),
                    leads: Vec::new(),
                    followers: Vec::new(),
                    alternatives: Vec::new(),
                    count_setter,
                });
                groups.len() - 1
            }
        };
        let optional = crate::model::attrs::parse_optional(m.optional.as_deref())
            .first()
            .copied()
            .unwrap_or(false);
        let g = &mut groups[i];
        if optional || m.noautovalidity {
            g.alternatives.push(m.name.clone());
        } else {
            g.leads.push(m.name.clone());
        }
    }
    for g in &mut groups {
        // Beside leads, an optional array follows the count they set; noautovalidity
        // arrays are read by condition (`descriptorType` picks one), so they stay
        // alternatives only where no lead exists.
        if !g.leads.is_empty() {
            g.followers = std::mem::take(&mut g.alternatives);
        }
    }
    groups.retain(|g| {
        g.leads.len() + g.followers.len() + g.alternatives.len() + usize::from(g.count_setter) > 1
    });
    groups
}
