//! The oracle's cases: for each recognised rule of a struct that `tests/oracle.rs`
//! has a fixture for, the change to that fixture's smallest valid value that breaks
//! exactly that rule, derived from the rule's check.
//!
//! The test runs each case twice: through the safe method, which must refuse it with
//! the rule's VUID, and through the `_unchecked` twin under the validation layer,
//! which must name the same VUID or nothing (the rule is then proven by the error
//! alone). A recognised rule is reported as dynamically settled only when it has a
//! case here; the others are checked in every build but counted as the user's.

use super::checks::Checker;
use super::Context;
use crate::model::Model;
use crate::validity::explicit::{Object, Op, Pred, Recognised, Rhs, Value};

/// The structs and commands `tests/oracle.rs` has a fixture for: a smallest valid
/// value and the safe call (and its `_unchecked` twin) that takes it. A struct's
/// fixture function is its name in snake case without `Vk`; a command's is its
/// method's name, over an `args::` struct of the parameters a rule can name.
pub const FIXTURES: &[&str] = &[
    "VkBufferCreateInfo",
    "VkImageCreateInfo",
    "VkSamplerCreateInfo",
    "VkMemoryBarrier2",
    "VkBufferMemoryBarrier2",
    "VkImageMemoryBarrier2",
    "VkDescriptorPoolCreateInfo",
    "VkDescriptorPoolSize",
    "VkPushConstantRange",
    "VkQueryPoolCreateInfo",
    "VkSubpassDependency",
    "VkSubpassDependency2",
    "VkAttachmentDescription",
    "VkAttachmentDescription2",
    "VkSubpassDescription",
    "VkSubpassDescription2",
    "VkPipelineColorBlendAttachmentState",
    "VkPipelineColorBlendStateCreateInfo",
    "VkPipelineRasterizationStateCreateInfo",
    "VkPipelineMultisampleStateCreateInfo",
    "VkVertexInputBindingDescription",
    "VkImageViewCreateInfo",
    "VkFramebufferCreateInfo",
    "VkCopyBufferInfo2",
    "VkCopyImageInfo2",
    "VkBlitImageInfo2",
    "VkCopyBufferToImageInfo2",
    "VkCopyImageToBufferInfo2",
    "vkCmdSetEvent",
    "vkCmdResetEvent",
    "vkCmdResetEvent2",
    "vkCmdWaitEvents",
    "vkCmdPipelineBarrier",
    "vkCmdWriteTimestamp",
    "vkCmdClearColorImage",
    "vkCmdCopyImage",
    "vkCmdCopyBufferToImage",
    "vkCmdCopyImageToBuffer",
    "vkCmdBlitImage",
    "vkCmdDrawIndirect",
    "vkCmdDrawIndexedIndirect",
    "vkCmdDispatchIndirect",
    "vkCmdResolveImage",
    "VkResolveImageInfo2",
    "vkCmdCopyQueryPoolResults",
    "VkBufferViewCreateInfo",
    "VkBufferMemoryBarrier",
    "VkImageMemoryBarrier",
];

/// Rules of fixture structs whose case the IR cannot build as one change, with why.
pub const SKIP: &[(&str, &str)] = &[
    ("VUID-VkBufferCreateInfo-flags-00916", SPARSE),
    ("VUID-VkBufferCreateInfo-flags-00917", SPARSE),
    ("VUID-VkImageCreateInfo-flags-01924", SPARSE),
    ("VUID-VkImageCreateInfo-tiling-04121", SPARSE),
    ("VUID-VkImageCreateInfo-imageType-00970", SPARSE),
    ("VUID-VkImageCreateInfo-imageType-00971", SPARSE),
    ("VUID-VkImageCreateInfo-imageType-00972", SPARSE),
    ("VUID-VkImageCreateInfo-imageType-00973", SPARSE),
    ("VUID-VkImageCreateInfo-imageType-00974", SPARSE),
    ("VUID-VkImageCreateInfo-imageType-00975", SPARSE),
    ("VUID-VkImageCreateInfo-imageType-00976", SPARSE),
    ("VUID-VkImageCreateInfo-extent-00946", "a depth of 0 also breaks `imageType-00957` (a 2D image has depth 1), and the fixture's image is 2D"),
    ("VUID-VkImageCreateInfo-flags-00949", ONE_D),
    ("VUID-VkImageCreateInfo-flags-00950", ONE_D),
    ("VUID-VkSamplerCreateInfo-unnormalizedCoordinates-01076", "enabling anisotropy also breaks `anisotropyEnable-01070` on a device without `samplerAnisotropy`"),
    ("VUID-VkPushConstantRange-offset-00294", "an offset at the limit leaves no room for a size, so `size-00298` breaks as well"),
    ("VUID-VkPipelineInputAssemblyStateCreateInfo-topology-00430", "a patch list without tessellation shaders also breaks `VkGraphicsPipelineCreateInfo-topology-00737`"),
    ("VUID-vkCmdWriteTimestamp2-stage-03929", ONE_STAGE),
    ("VUID-vkCmdWriteTimestamp2-stage-03930", ONE_STAGE),
    ("VUID-VkFramebufferCreateInfo-width-00886", PAST_ATTACHMENT),
    ("VUID-VkFramebufferCreateInfo-height-00888", PAST_ATTACHMENT),
    ("VUID-VkFramebufferCreateInfo-layers-00890", PAST_ATTACHMENT),
    ("VUID-VkImageViewCreateInfo-viewType-01004", "a cube-array view of the fixture's one layer also breaks `viewType-02961` (a multiple of six layers)"),
    ("VUID-VkImageViewCreateInfo-subresourceRange-01478", "a base level at the image's level count also puts base plus count past it, which breaks `subresourceRange-01718` as well"),
    ("VUID-VkImageMemoryBarrier2-subresourceRange-01486", "a base level at the image's level count also puts base plus count past it, which breaks `subresourceRange-01724` as well"),
    ("VUID-VkImageMemoryBarrier-subresourceRange-01486", "as for `VkImageMemoryBarrier2`: `subresourceRange-01724` breaks as well"),
    ("VUID-VkImageMemoryBarrier-subresourceRange-01488", "as for `VkImageMemoryBarrier2`: the 1.3.239 layer throws a C++ exception on it"),
    ("VUID-VkImageMemoryBarrier2-subresourceRange-01488", "the 1.3.239 validation layer throws a C++ exception (which aborts the test) on a barrier whose layer is past the image's"),
    ("VUID-vkCmdDrawIndirect-drawCount-02719", MULTI_DRAW),
    ("VUID-vkCmdDrawIndexedIndirect-drawCount-02719", MULTI_DRAW),
    ("VUID-VkVertexInputAttributeDescription-binding-00621", "a binding past the limit has no binding description, so `VkPipelineVertexInputStateCreateInfo-binding-00615` breaks as well"),
];

const SPARSE: &str = "setting a sparse residency or aliased bit needs `SPARSE_BINDING` too, which breaks the `sparseBinding` rule as well on a device without sparse features";
const PAST_ATTACHMENT: &str = "a framebuffer larger than the limit is larger than its attachment too, which breaks `flags-04533` (or `04534`, `04535`) as well";
const MULTI_DRAW: &str = "a draw count past the limit is more than one draw, which breaks `drawCount-02718` as well on a device without `multiDrawIndirect`";
const ONE_STAGE: &str = "the stage is a single bit; the case adds the forbidden one to the fixture's, which breaks `stage-03859` as well";
const ONE_D: &str = "the other image type the case picks is 1D, and the fixture's 4x4 image breaks `imageType-00956` (a 1D image has height 1) as well";

/// One change to a fixture's value.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Assign {
    /// Set these bits of a flags member (`|=`).
    SetBits {
        /// The member path.
        member: String,
        /// The flags type (`VkImageCreateFlags`).
        ty: String,
        /// The bits.
        bits: u64,
    },
    /// Replace a flags member with exactly these bits.
    Bits {
        /// The member path.
        member: String,
        /// The flags type.
        ty: String,
        /// The bits.
        bits: u64,
    },
    /// Clear these bits of a flags member.
    ClearBits {
        /// The member path.
        member: String,
        /// The flags type.
        ty: String,
        /// The bits.
        bits: u64,
    },
    /// Set an enum member.
    Enum {
        /// The member path.
        member: String,
        /// The enum type.
        ty: String,
        /// The value.
        value: i64,
    },
    /// Create the object a handle names without these usage bits.
    ClearUsage {
        /// The handle's path.
        handle: String,
        /// What it names.
        object: Object,
        /// The bits.
        bits: u64,
    },
    /// Create the object a handle names without binding memory to it.
    Unbound {
        /// The handle's path.
        handle: String,
    },
    /// Set a `VkBool32` or number member to a Rust expression over `v` (the value),
    /// `l` (the device's limits) and `o` (how the fixture makes its objects).
    Number {
        /// The member path.
        member: String,
        /// The expression.
        expr: String,
    },
}

impl Assign {
    /// The member path the change sets.
    pub fn member(&self) -> &str {
        match self {
            Assign::SetBits { member, .. }
            | Assign::Bits { member, .. }
            | Assign::ClearBits { member, .. }
            | Assign::Enum { member, .. }
            | Assign::Number { member, .. } => member,
            Assign::ClearUsage { handle, .. } | Assign::Unbound { handle } => handle,
        }
    }
}

/// One case: the rule and the changes that break it.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Case {
    /// The rule.
    pub vuid: String,
    /// The struct (the fixture).
    pub item: String,
    /// Whether its ash type has a lifetime (`vk::MemoryBarrier2<'_>`).
    pub lifetime: bool,
    /// The item is a command: the fixture's value is the test's `args::Cmd*`
    /// struct of its parameters.
    pub on_command: bool,
    /// The changes, in order.
    pub assigns: Vec<Assign>,
}

/// The cases of every recognised rule of a fixture struct that some emitted command
/// checks.
pub fn cases(cx: &Context, checker: &Checker) -> Vec<Case> {
    cx.validity
        .recognised
        .iter()
        .filter(|r| FIXTURES.contains(&r.item.as_str()) && checker.dynamic(&r.vuid).is_some())
        .filter(|r| !SKIP.iter().any(|(v, _)| *v == r.vuid))
        .filter_map(|r| case(cx.model, r))
        .map(|c| Case {
            lifetime: cx.facts.has_lifetime(&c.item),
            ..c
        })
        .collect()
}

fn case(model: &Model, r: &Recognised) -> Option<Case> {
    let mut assigns = Vec::new();
    for p in &r.check.when {
        make_true(model, &r.item, p, &mut assigns)?;
    }
    make_false(model, &r.item, &r.check.must, &mut assigns)?;
    // A count that goes with a pointer member is not the fixture's to change: the
    // safe struct's setters keep the two together.
    let fields = match model.commands.get(&r.item) {
        Some(cmd) => &cmd.params,
        None => &model.types.get(&r.item)?.members,
    };
    let counts: Vec<&str> = fields
        .iter()
        .filter_map(|m| m.len.as_deref()?.split(',').next())
        .collect();
    if assigns.iter().any(|a| counts.contains(&a.member())) {
        return None;
    }
    Some(Case {
        vuid: r.vuid.clone(),
        item: r.item.clone(),
        lifetime: false,
        on_command: r.on_command,
        assigns,
    })
}

/// The C type of a member path (of a command's parameters, for a command).
fn member_type(model: &Model, item: &str, path: &str) -> Option<String> {
    let mut parts = path.split('.');
    let mut ty = item.to_owned();
    if let Some(cmd) = model.commands.get(item) {
        let first = parts.next()?;
        ty = cmd
            .params
            .iter()
            .find(|p| p.name == first)?
            .type_name
            .clone();
    }
    for part in parts {
        ty = model
            .types
            .get(&ty)?
            .members
            .iter()
            .find(|m| m.name == part)?
            .type_name
            .clone();
    }
    Some(ty)
}

fn mask(bits: &[Value]) -> u64 {
    bits.iter().fold(0, |acc, b| acc | b.number as u64)
}

/// Changes that make a condition hold. The fixtures' device enables no Vulkan 1.0
/// feature, so "feature not enabled" holds already.
fn make_true(model: &Model, item: &str, p: &Pred, out: &mut Vec<Assign>) -> Option<()> {
    match p {
        Pred::Feature { enabled: false, .. } => {}
        Pred::AnyBit { member, bits } => out.push(Assign::SetBits {
            ty: member_type(model, item, member)?,
            member: member.clone(),
            bits: bits.first()?.number as u64,
        }),
        Pred::NoBit { member, bits } => out.push(Assign::ClearBits {
            ty: member_type(model, item, member)?,
            member: member.clone(),
            bits: mask(bits),
        }),
        Pred::OneOf { member, values } => out.push(value_of(model, item, member, values.first()?)?),
        Pred::Compare {
            member,
            op: Op::Eq,
            rhs: Rhs::Const(c),
            float,
            ..
        } => out.push(Assign::Number {
            member: member.clone(),
            expr: crate::validity::explicit::number(c, *float),
        }),
        _ => return None,
    }
    Some(())
}

/// Changes that make a requirement fail.
fn make_false(model: &Model, item: &str, p: &Pred, out: &mut Vec<Assign>) -> Option<()> {
    match p {
        Pred::AnyBit { member, bits } => {
            let ty = member_type(model, item, member)?;
            let group = model.types.get(&ty)?.bit_values.clone()?;
            let other = first_other(model, &group, bits, true)?;
            out.push(Assign::Bits {
                member: member.clone(),
                ty,
                bits: other.number as u64,
            });
        }
        Pred::NoBit { member, bits } => out.push(Assign::SetBits {
            ty: member_type(model, item, member)?,
            member: member.clone(),
            bits: bits.first()?.number as u64,
        }),
        Pred::NoneOf { member, values } => {
            out.push(value_of(model, item, member, values.first()?)?)
        }
        Pred::OneOf { member, values } if crate::validity::explicit::is_bool(values) => {
            // A number outside the list (`drawCount` of 2 for `0 or 1`), or the other
            // `VkBool32`.
            let numbers = values
                .iter()
                .all(|v| v.name.starts_with(|c: char| c.is_ascii_digit()));
            let v = if numbers {
                values.iter().map(|v| v.number).max()? + 1
            } else if values.iter().any(|v| v.number == 1) {
                0
            } else {
                1
            };
            out.push(Assign::Number {
                member: member.clone(),
                expr: v.to_string(),
            });
        }
        Pred::OneOf { member, values } => {
            let ty = member_type(model, item, member)?;
            let other = first_other(model, &ty, values, false)?;
            out.push(Assign::Enum {
                member: member.clone(),
                ty,
                value: other.number,
            });
        }
        Pred::Usage {
            handle,
            object,
            bits,
        } => out.push(Assign::ClearUsage {
            handle: handle.clone(),
            object: *object,
            bits: mask(bits),
        }),
        Pred::Bound { handle, .. } => out.push(Assign::Unbound {
            handle: handle.clone(),
        }),
        Pred::Compare {
            member,
            op: Op::Lt,
            rhs: Rhs::Created { handle, field, .. },
            ..
        } => out.push(Assign::Number {
            member: member.clone(),
            expr: format!(
                "o.{}.{} as _",
                crate::names::param(handle),
                crate::names::field(field)
            ),
        }),
        Pred::Compare {
            member,
            op,
            rhs,
            float,
            ..
        } => {
            let one = if *float { "1.0" } else { "1" };
            let expr = match (rhs, op) {
                (Rhs::Const(c), Op::Gt | Op::Lt | Op::Ne) => {
                    crate::validity::explicit::number(c, *float)
                }
                (Rhs::Const(c), Op::Le | Op::Eq) => shifted(c, *float, 1)?,
                (Rhs::Const(c), Op::Ge) if c != "0" => shifted(c, *float, -1)?,
                (Rhs::Limit(l), Op::Lt) => format!("l.{} as _", crate::names::field(l)),
                (Rhs::Limit(l), Op::Le) => {
                    format!("(l.{} as u64 + 1) as _", crate::names::field(l))
                }
                (Rhs::Member(m), Op::Gt | Op::Lt) => format!("v.{}", path(m, false)),
                (Rhs::Member(m), Op::Ge) => format!("v.{} - {one}", path(m, false)),
                (Rhs::Member(m), Op::Le) => format!("v.{} + {one}", path(m, false)),
                _ => return None,
            };
            out.push(Assign::Number {
                member: member.clone(),
                expr,
            });
        }
        _ => return None,
    }
    Some(())
}

/// A constant of the text moved by `by`, as a literal of the compared type.
fn shifted(c: &str, float: bool, by: i64) -> Option<String> {
    if float {
        let v: f64 = c.parse().ok()?;
        Some(crate::validity::explicit::number(
            &format!("{}", v + by as f64),
            true,
        ))
    } else {
        let v: i64 = c.parse().ok()?;
        Some((v + by).to_string())
    }
}

/// A member path in Rust (`extent.width`); a command's parameter is named as the
/// safe method names it.
pub fn path(p: &str, on_command: bool) -> String {
    p.split('.')
        .enumerate()
        .map(|(i, s)| {
            if i == 0 && on_command {
                crate::names::param(s)
            } else {
                crate::names::field(s)
            }
        })
        .collect::<Vec<_>>()
        .join(".")
}

fn value_of(model: &Model, item: &str, member: &str, v: &Value) -> Option<Assign> {
    let ty = member_type(model, item, member)?;
    Some(if ty == "VkBool32" {
        Assign::Number {
            member: member.to_owned(),
            expr: v.number.to_string(),
        }
    } else {
        Assign::Enum {
            member: member.to_owned(),
            ty,
            value: v.number,
        }
    })
}

/// The first value of a group that a core version defines and the list does not
/// name (for bits, a bit rather than 0).
fn first_other(model: &Model, group: &str, listed: &[Value], bits: bool) -> Option<Value> {
    model
        .enum_values
        .get(group)?
        .iter()
        .filter(|n| {
            model
                .enum_origins
                .get(*n)
                .is_some_and(|o| o.iter().any(|x| x.starts_with("VK_VERSION_")))
        })
        .filter_map(|n| {
            Some(Value {
                name: n.clone(),
                number: *model.enum_numbers.get(n)?,
            })
        })
        .find(|v| {
            !listed.iter().any(|l| l.number == v.number)
                && v.number != 0x7FFF_FFFF
                && (!bits || (v.number as u64).is_power_of_two())
        })
}
