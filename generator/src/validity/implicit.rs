//! Derivation of the implicit valid-usage rules from the model, following the rules
//! of the specification's own validity generator: which parameters and members get a
//! `-parameter` rule, when `sType`, `pNext` and `unique` rules exist, array lengths,
//! bitmasks, handle parents and the command-buffer state rules of `vkCmd*` commands.
//!
//! Only the VUIDs and a short statement of each rule are produced; the specification
//! text itself stays in validusage.json.

use crate::model::Kind;
use crate::model::{CommandDef, Field, TypeDef};
use crate::model::{LenEntry, Model};
use std::collections::BTreeMap;

/// What an implicit rule checks.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash, serde::Serialize)]
#[serde(rename_all = "lowercase")]
pub enum ImplicitKind {
    /// A valid handle, pointer, enum value, flags value or string.
    Parameter,
    /// `sType` has the struct's value.
    SType,
    /// `pNext` is NULL or points to structs that extend this one.
    PNext,
    /// No struct type appears twice in the `pNext` chain.
    Unique,
    /// A count that sizes an array is not zero.
    ArrayLength,
    /// A flags value is not zero.
    RequiredBitmask,
    /// A flags value with no defined bits is zero.
    ZeroBitmask,
    /// A handle comes from the parent passed beside it.
    Parent,
    /// Handles share a common parent.
    CommonParent,
    /// The command buffer is recording.
    Recording,
    /// The command buffer's pool supports the command's queue types.
    CmdPool,
    /// Called inside or outside a render pass, as the command requires.
    RenderPass,
    /// Recorded into a primary or secondary buffer, as the command requires.
    BufferLevel,
    /// Called inside or outside video coding, as the command requires.
    VideoCoding,
    /// The queue supports the command's queue types.
    QueueType,
    /// The command buffer is not in a suspended render pass instance (newer
    /// toolchains: commands whose `tasks` include action or synchronization).
    Suspended,
    /// The device was created with at least one queue (newer toolchains: `vkCreate*`
    /// and `vkAllocate*` of a device without `allownoqueues`).
    QueueCount,
}

impl ImplicitKind {
    /// The VUID suffix of the kind.
    pub fn tag(self) -> &'static str {
        match self {
            ImplicitKind::Parameter => "parameter",
            ImplicitKind::SType => "sType",
            ImplicitKind::PNext => "pNext",
            ImplicitKind::Unique => "unique",
            ImplicitKind::ArrayLength => "arraylength",
            ImplicitKind::RequiredBitmask => "requiredbitmask",
            ImplicitKind::ZeroBitmask => "zerobitmask",
            ImplicitKind::Parent => "parent",
            ImplicitKind::CommonParent => "commonparent",
            ImplicitKind::Recording => "recording",
            ImplicitKind::CmdPool => "cmdpool",
            ImplicitKind::RenderPass => "renderpass",
            ImplicitKind::BufferLevel => "bufferlevel",
            ImplicitKind::VideoCoding => "videocoding",
            ImplicitKind::QueueType => "queuetype",
            ImplicitKind::Suspended => "suspended",
            ImplicitKind::QueueCount => "queuecount",
        }
    }

    /// Whether VUIDs of this kind name a parameter (`VUID-item-param-tag`) or not
    /// (`VUID-item-tag`).
    pub fn names_parameter(self) -> bool {
        !matches!(
            self,
            ImplicitKind::CommonParent
                | ImplicitKind::RenderPass
                | ImplicitKind::BufferLevel
                | ImplicitKind::VideoCoding
                | ImplicitKind::QueueType
                | ImplicitKind::Suspended
        )
    }

    /// The kind whose tag is `tag`.
    pub fn from_tag(tag: &str) -> Option<ImplicitKind> {
        ALL_KINDS.iter().copied().find(|k| k.tag() == tag)
    }
}

const ALL_KINDS: [ImplicitKind; 17] = [
    ImplicitKind::Parameter,
    ImplicitKind::SType,
    ImplicitKind::PNext,
    ImplicitKind::Unique,
    ImplicitKind::ArrayLength,
    ImplicitKind::RequiredBitmask,
    ImplicitKind::ZeroBitmask,
    ImplicitKind::Parent,
    ImplicitKind::CommonParent,
    ImplicitKind::Recording,
    ImplicitKind::CmdPool,
    ImplicitKind::RenderPass,
    ImplicitKind::BufferLevel,
    ImplicitKind::VideoCoding,
    ImplicitKind::QueueType,
    ImplicitKind::Suspended,
    ImplicitKind::QueueCount,
];

/// True when `vuid` has the shape of an implicit rule: `VUID-item-param-tag` or
/// `VUID-item-tag` with a tag of [`ImplicitKind`]. `sType` and `pNext` rules must
/// repeat the member name (`VUID-X-pNext-pNext`), which is what tells the malformed
/// explicit `VUID-VkInstanceCreateInfo-pNext` of 1.3.239 apart.
pub fn is_implicit_vuid(vuid: &str) -> bool {
    let parts: Vec<&str> = vuid.split('-').collect();
    let Some(kind) = parts.last().and_then(|t| ImplicitKind::from_tag(t)) else {
        return false;
    };
    match (kind.names_parameter(), parts.len()) {
        (false, 3) => true,
        (true, 4) => match kind {
            ImplicitKind::SType | ImplicitKind::Unique => parts[2] == "sType",
            ImplicitKind::PNext => parts[2] == "pNext",
            ImplicitKind::Recording | ImplicitKind::CmdPool => parts[2] == "commandBuffer",
            ImplicitKind::QueueCount => parts[2] == "device",
            _ => true,
        },
        _ => false,
    }
}

/// Where the specification's generator changed its rules between releases. Each
/// change is placed right after the last registry known to follow the older rule
/// (validusage.json or the toolchain's list, in `../shared/registry/`), so a registry
/// newer than every one in the repository gets the newest rules.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Toolchain {
    /// `-parent` looks up the whole parent chain for a parameter of an ancestor's
    /// type (newer), not just the direct parent (older). After 1.3.239 (1.3.281 has it).
    pub parent_chain: bool,
    /// `-requiredbitmask` is skipped when any level of `optional` is true (newer),
    /// rather than only when `optional` is exactly `true` (older). After 1.3.239.
    pub requiredbitmask_any_optional: bool,
    /// `-suspended` for recorded commands whose `tasks` include action or
    /// synchronization. After 1.4.309 (1.4.330 has it).
    pub suspended: bool,
    /// `-device-queuecount` for `vkCreate*` and `vkAllocate*` commands of a device
    /// that lack `allownoqueues`. After 1.4.309.
    pub queuecount: bool,
    /// `-parameter` for `VkDeviceAddress` members and parameters. After 1.4.309.
    pub device_address: bool,
}

impl Toolchain {
    /// The rules of the toolchain that published a registry of this version
    /// (`major.minor.patch`; missing numbers read as 0).
    pub fn for_version(version: &str) -> Toolchain {
        let mut nums = version.split('.').map(|n| n.parse::<u32>().unwrap_or(0));
        let v = (
            nums.next().unwrap_or(1),
            nums.next().unwrap_or(0),
            nums.next().unwrap_or(0),
        );
        let after_1_3_239 = v > (1, 3, 239);
        let after_1_4_309 = v > (1, 4, 309);
        Toolchain {
            parent_chain: after_1_3_239,
            requiredbitmask_any_optional: after_1_3_239,
            suspended: after_1_4_309,
            queuecount: after_1_4_309,
            device_address: after_1_4_309,
        }
    }
}

/// One derived implicit rule.
#[derive(Debug, Clone, PartialEq, Eq, serde::Serialize)]
pub struct DerivedRule {
    /// The VUID.
    pub vuid: String,
    /// The command or struct.
    pub item: String,
    /// What it checks.
    pub kind: ImplicitKind,
    /// The parameter or member it is about, if any.
    pub field: Option<String>,
    /// A one-line statement of the rule.
    pub text: String,
    /// The other parameters or members the rule names: the parent of a `parent`
    /// rule, every handle of a `commonparent` rule.
    pub related: Vec<String>,
    /// The handle type a `parent` or `commonparent` rule's handles must come from.
    pub ancestor: Option<String>,
}

/// Derive the implicit rules of every command and struct the all-extensions build
/// contains, in item-name order.
pub fn derive_all(model: &Model, toolchain: Toolchain) -> Vec<DerivedRule> {
    let mut d = Deriver::new(model, toolchain);
    for (name, t) in &model.types {
        if t.alias.is_none() && t.category == Some(Kind::Struct) && model.required.contains(name) {
            d.derive_struct(t);
        }
    }
    for name in model.commands.keys() {
        if model.required.contains(name) {
            if let Some(c) = resolve_command(model, name) {
                d.block(name, Some(c), None, &c.params);
            }
        }
    }
    d.out
}

/// A command's definition; an alias gets the definition of the command it names, as
/// the specification's toolchain copies it under the alias's name.
fn resolve_command<'m>(model: &'m Model, name: &str) -> Option<&'m CommandDef> {
    let mut c = model.commands.get(name)?;
    for _ in 0..4 {
        match &c.alias {
            Some(target) => c = model.commands.get(target)?,
            None => return Some(c),
        }
    }
    None
}

/// Derive the implicit rules of one command or struct.
pub fn derive_item(model: &Model, toolchain: Toolchain, item: &str) -> Vec<DerivedRule> {
    let mut d = Deriver::new(model, toolchain);
    if let Some(t) = model.types.get(item) {
        if t.category == Some(Kind::Struct) {
            d.derive_struct(t);
        }
    } else if let Some(c) = resolve_command(model, item) {
        d.block(item, Some(c), None, &c.params);
    }
    d.out
}

struct Deriver<'a> {
    model: &'a Model,
    tc: Toolchain,
    out: Vec<DerivedRule>,
    video: bool,
}

impl<'a> Deriver<'a> {
    fn new(model: &'a Model, tc: Toolchain) -> Self {
        Deriver {
            model,
            tc,
            out: Vec::new(),
            // Video-coding rules exist only in registries with the video extensions.
            video: model.required.contains("vkCmdBeginVideoCodingKHR"),
        }
    }

    fn push(&mut self, item: &str, field: Option<&str>, kind: ImplicitKind, text: String) {
        let vuid = match field {
            Some(f) => format!("VUID-{item}-{f}-{}", kind.tag()),
            None => format!("VUID-{item}-{}", kind.tag()),
        };
        self.out.push(DerivedRule {
            vuid,
            item: item.to_owned(),
            kind,
            field: field.map(str::to_owned),
            text,
            related: Vec::new(),
            ancestor: None,
        });
    }

    fn derive_struct(&mut self, t: &'a TypeDef) {
        if t.returned_only {
            // The implementation fills it in: only the chain members are checked.
            for m in &t.members {
                self.shared_member(Some(t), &t.name, m);
            }
        } else {
            self.block(&t.name, None, Some(t), &t.members);
        }
    }

    fn category(&self, type_name: &str) -> Option<Kind> {
        self.model.category(type_name)
    }

    /// `sType` and `pNext`: returns true when the member was one of them.
    fn shared_member(&mut self, s: Option<&TypeDef>, block: &str, m: &Field) -> bool {
        if m.noautovalidity {
            return false;
        }
        if m.type_name == "VkStructureType" && m.name == "sType" {
            let value = m.values.clone().unwrap_or_default();
            self.push(
                block,
                Some("sType"),
                ImplicitKind::SType,
                format!("`sType` must be `{value}`"),
            );
            return true;
        }
        if m.type_name == "void" && m.name == "pNext" {
            let extends_others = s.is_some_and(|s| !s.struct_extends.is_empty());
            if !extends_others {
                let extenders: Vec<&String> = self
                    .model
                    .extended_by
                    .get(block)
                    .into_iter()
                    .flatten()
                    .filter(|e| self.model.required.contains(*e))
                    .collect();
                if extenders.is_empty() {
                    self.push(
                        block,
                        Some("pNext"),
                        ImplicitKind::PNext,
                        "`pNext` must be `NULL`".into(),
                    );
                } else {
                    let list = extenders
                        .iter()
                        .map(|e| format!("`{e}`"))
                        .collect::<Vec<_>>()
                        .join(", ");
                    self.push(
                        block,
                        Some("pNext"),
                        ImplicitKind::PNext,
                        format!(
                            "each `pNext` in the chain must be `NULL` or point to a valid {list}"
                        ),
                    );
                    self.push(
                        block,
                        Some("sType"),
                        ImplicitKind::Unique,
                        "the `sType` of each struct in the `pNext` chain must be unique".into(),
                    );
                }
            }
            return true;
        }
        false
    }

    fn block(
        &mut self,
        block: &str,
        cmd: Option<&CommandDef>,
        s: Option<&TypeDef>,
        params: &'a [Field],
    ) {
        let mut handles: Vec<&'a Field> = Vec::new();
        let mut array_lengths: BTreeMap<String, LenEntry> = BTreeMap::new();
        for p in params {
            let category = self.category(&p.type_name);
            if !self.shared_member(s, block, p) {
                match (&p.selector, self.model.types.get(&p.type_name)) {
                    (Some(_), Some(union)) => {
                        for m in &union.members {
                            let mc = self.category(&m.type_name);
                            self.line(block, m, &union.members, mc);
                        }
                    }
                    _ => self.line(block, p, params, category),
                }
            }
            if category == Some(Kind::Handle) {
                handles.push(p);
            }
            if let Some(len) = &p.len {
                for entry in crate::model::attrs::parse_len(len) {
                    if let Some(other) = entry.other_param() {
                        array_lengths.insert(other.to_owned(), entry.clone());
                    }
                }
            }
        }

        if let Some(cmd) = cmd {
            self.command_state(block, cmd);
        }
        self.array_lengths(block, params, &array_lengths);

        for h in &handles {
            if h.pointers == 0 || h.is_const {
                self.parent(block, h, params);
            }
        }
        self.common_parent(block, &handles);
    }

    fn command_state(&mut self, block: &str, cmd: &CommandDef) {
        let creates = block.starts_with("vkCreate") || block.starts_with("vkAllocate");
        let on_device = cmd
            .params
            .first()
            .is_some_and(|p| p.type_name == "VkDevice");
        if self.tc.queuecount && creates && on_device && !cmd.allownoqueues {
            self.push(
                block,
                Some("device"),
                ImplicitKind::QueueCount,
                "`device` must have been created with at least one queue".into(),
            );
        }
        if block.contains("vkQueue") {
            if let Some(queues) = &cmd.queues {
                self.push(
                    block,
                    None,
                    ImplicitKind::QueueType,
                    format!("the queue must support {queues} operations"),
                );
            }
        }
        if !block.contains("vkCmd") {
            return;
        }
        self.push(
            block,
            Some("commandBuffer"),
            ImplicitKind::Recording,
            "`commandBuffer` must be in the recording state".into(),
        );
        let queues = cmd.queues.clone().unwrap_or_default();
        self.push(
            block,
            Some("commandBuffer"),
            ImplicitKind::CmdPool,
            format!("the pool of `commandBuffer` must support {queues} operations"),
        );
        let renderpass = cmd.renderpass.as_deref().unwrap_or("");
        if renderpass != "both" {
            self.push(
                block,
                None,
                ImplicitKind::RenderPass,
                format!("must only be called {renderpass} a render pass instance"),
            );
        }
        if self.video {
            let videocoding = cmd.videocoding.as_deref().unwrap_or("outside");
            if videocoding != "both" {
                self.push(
                    block,
                    None,
                    ImplicitKind::VideoCoding,
                    format!("must only be called {videocoding} a video coding scope"),
                );
            }
        }
        let tasks = cmd.tasks.as_deref().unwrap_or("");
        let acts = tasks
            .split(',')
            .any(|t| t == "action" || t == "synchronization");
        if self.tc.suspended && acts && cmd.cmdbufferlevel.is_some() {
            self.push(
                block,
                None,
                ImplicitKind::Suspended,
                "`commandBuffer` must not be in a suspended render pass instance".into(),
            );
        }
        let level = cmd.cmdbufferlevel.as_deref().unwrap_or("");
        if level != "primary,secondary" {
            self.push(
                block,
                None,
                ImplicitKind::BufferLevel,
                format!("`commandBuffer` must be a {level} command buffer"),
            );
        }
    }

    fn array_lengths(
        &mut self,
        block: &str,
        params: &'a [Field],
        lengths: &BTreeMap<String, LenEntry>,
    ) {
        for p in params {
            let Some(entry) = lengths.get(&p.name) else {
                continue;
            };
            if p.optional.is_some() || p.deprecated.as_deref() == Some("unused") {
                continue;
            }
            let LenEntry::Reference(parts) = entry else {
                continue;
            };
            if parts.len() > 1 {
                // `pInfo->count`: no rule when any step of the path is optional.
                let mut fields: &[Field] = params;
                let mut optional = false;
                for part in parts {
                    let Some(f) = fields.iter().find(|f| &f.name == part) else {
                        break;
                    };
                    optional |= f.optional.is_some();
                    fields = self
                        .model
                        .types
                        .get(&f.type_name)
                        .map_or(&[], |t| &t.members);
                }
                if optional {
                    continue;
                }
            }
            let name = entry.vuid_name().unwrap_or_default();
            self.push(
                block,
                Some(&name),
                ImplicitKind::ArrayLength,
                format!("`{}` must be greater than 0", name),
            );
        }
    }

    fn parent(&mut self, block: &str, h: &Field, params: &[Field]) {
        let mut t = h.type_name.clone();
        let mut steps = 0;
        let parent_param = loop {
            // A malformed registry could make the parents a cycle.
            steps += 1;
            if steps > 16 {
                return;
            }
            let Some(parent) = self.model.types.get(&t).and_then(|x| x.parent.clone()) else {
                return;
            };
            if let Some(p) = params.iter().find(|p| p.type_name == parent) {
                break p;
            }
            if !self.tc.parent_chain {
                return;
            }
            t = parent;
        };
        self.push(
            block,
            Some(&h.name),
            ImplicitKind::Parent,
            format!(
                "`{}` must have been created, allocated or retrieved from `{}`",
                h.name, parent_param.name
            ),
        );
        if let Some(rule) = self.out.last_mut() {
            rule.related = vec![parent_param.name.clone()];
            rule.ancestor = Some(parent_param.type_name.clone());
        }
    }

    fn dispatchable_ancestors(&self, type_name: &str) -> Vec<String> {
        let mut out = Vec::new();
        let mut current = type_name.to_owned();
        while let Some(parent) = self
            .model
            .types
            .get(&current)
            .and_then(|t| t.parent.clone())
        {
            if out.contains(&parent) || out.len() > 16 {
                break;
            }
            if self
                .model
                .types
                .get(&parent)
                .is_some_and(|t| t.dispatchable && t.category == Some(Kind::Handle))
            {
                out.push(parent.clone());
            }
            current = parent;
        }
        out
    }

    fn common_parent(&mut self, block: &str, handles: &[&Field]) {
        if handles.len() < 2 {
            return;
        }
        let mut ancestors: Vec<(&Field, Vec<String>)> = handles
            .iter()
            .filter(|h| h.pointers == 0 || h.is_const)
            .map(|h| (*h, self.dispatchable_ancestors(&h.type_name)))
            .collect();
        // A handle whose ancestor is itself passed is covered by the `-parent` rule.
        ancestors.retain(|(_, anc)| !handles.iter().any(|h| anc.contains(&h.type_name)));
        if ancestors.len() < 2 {
            return;
        }
        let mut common = ancestors[0].1.clone();
        for (_, anc) in &ancestors[1..] {
            common.retain(|a| anc.contains(a));
        }
        if let Some(ancestor) = common.first() {
            let mut names: Vec<String> = ancestors
                .iter()
                .map(|(h, _)| format!("`{}`", h.name))
                .collect();
            names.sort();
            self.push(
                block,
                None,
                ImplicitKind::CommonParent,
                format!("{} must come from the same `{ancestor}`", names.join(", ")),
            );
            if let Some(rule) = self.out.last_mut() {
                rule.related = ancestors.iter().map(|(h, _)| h.name.clone()).collect();
                rule.ancestor = Some(ancestor.clone());
            }
        }
    }

    fn bits_defined(&self, flags: &str) -> bool {
        bits_by_name(self.model, flags).1
    }

    fn struct_always_valid(&self, name: &str, depth: usize) -> bool {
        const ALWAYS_VALID: [&str; 14] = [
            "char",
            "float",
            "int8_t",
            "uint8_t",
            "int16_t",
            "uint16_t",
            "int32_t",
            "uint32_t",
            "int64_t",
            "uint64_t",
            "size_t",
            "intptr_t",
            "uintptr_t",
            "int",
        ];
        if ALWAYS_VALID.contains(&name) {
            return true;
        }
        if matches!(
            self.category(name),
            Some(Kind::Handle | Kind::Enum | Kind::Bitmask)
        ) {
            return false;
        }
        let Some(t) = self.model.types.get(name) else {
            return true;
        };
        if depth > 32 {
            return false;
        }
        for m in &t.members {
            if m.name == "sType" || m.name == "pNext" || m.noautovalidity {
                return false;
            }
            if m.type_name == "void" || m.type_name == "char" || m.len.is_some() || m.pointers > 0 {
                return false;
            }
            if ALWAYS_VALID.contains(&m.type_name.as_str()) {
                continue;
            }
            match self.category(&m.type_name) {
                Some(Kind::Handle | Kind::Enum | Kind::Bitmask) => return false,
                Some(Kind::Struct | Kind::Union)
                    if !self.struct_always_valid(&m.type_name, depth + 1) =>
                {
                    return false
                }
                _ => {}
            }
        }
        true
    }

    /// The `-parameter`, `-requiredbitmask` and `-zerobitmask` rules of one parameter.
    fn line(&mut self, block: &str, p: &Field, params: &[Field], category: Option<Kind>) {
        let is_array = p.len.is_some();
        let is_pointer = p.pointers > 0;
        let t = p.type_name.as_str();
        let checked = if t == "void" || t == "char" {
            true
        } else {
            match category {
                Some(Kind::Bitmask) => {
                    if !self.bits_defined(t) {
                        self.push(
                            block,
                            Some(&p.name),
                            ImplicitKind::ZeroBitmask,
                            format!("`{}` must be 0", p.name),
                        );
                        return;
                    }
                    true
                }
                Some(Kind::Handle | Kind::Enum | Kind::Funcpointer) => true,
                Some(Kind::Struct | Kind::Union) => {
                    is_array || is_pointer || !self.struct_always_valid(t, 0)
                }
                _ if is_array || is_pointer => true,
                None => !self.struct_always_valid(t, 0),
                // Newer toolchains ask a valid device address.
                _ => self.tc.device_address && t == "VkDeviceAddress",
            }
        };
        if checked {
            self.parameter(block, p, params, category);
        }
    }

    fn parameter(&mut self, block: &str, p: &Field, _params: &[Field], category: Option<Kind>) {
        if p.noautovalidity {
            return;
        }
        let optional = crate::model::attrs::parse_optional(p.optional.as_deref());
        let what = describe(p, category);
        if p.static_array.is_some() && p.type_name == "char" {
            self.push(block, Some(&p.name), ImplicitKind::Parameter, what);
            return;
        }
        let bitmask = category == Some(Kind::Bitmask);
        if let Some(len) = &p.len {
            let levels = crate::model::attrs::parse_len(len).len();
            let element_optional = optional.len() == levels + 1 && optional.last() == Some(&true);
            self.push(block, Some(&p.name), ImplicitKind::Parameter, what);
            let skip = if self.tc.requiredbitmask_any_optional {
                optional.iter().any(|o| *o)
            } else {
                element_optional
            };
            if bitmask && !skip {
                self.required_bitmask(block, p);
            }
            return;
        }
        if p.pointers > 0 {
            if p.type_name == "void" && p.pointers == 1 && p.optional.is_some() {
                return;
            }
            self.push(block, Some(&p.name), ImplicitKind::Parameter, what);
            return;
        }
        self.push(block, Some(&p.name), ImplicitKind::Parameter, what);
        let skip = if self.tc.requiredbitmask_any_optional {
            optional.iter().any(|o| *o)
        } else {
            p.optional.as_deref() == Some("true")
        };
        if bitmask && !skip {
            self.required_bitmask(block, p);
        }
    }

    fn required_bitmask(&mut self, block: &str, p: &Field) {
        self.push(
            block,
            Some(&p.name),
            ImplicitKind::RequiredBitmask,
            format!("`{}` must not be 0", p.name),
        );
    }
}

fn describe(p: &Field, category: Option<Kind>) -> String {
    let t = &p.type_name;
    let noun = match category {
        Some(Kind::Handle) => format!("a valid `{t}` handle"),
        Some(Kind::Enum) => format!("a valid `{t}` value"),
        Some(Kind::Bitmask) => format!(
            "a valid combination of `{}` values",
            t.replace("Flags", "FlagBits")
        ),
        Some(Kind::Struct) => format!("a valid `{t}` structure"),
        Some(Kind::Union) => format!("a valid `{t}` union"),
        Some(Kind::Funcpointer) => format!("a valid `{t}` value"),
        _ if t == "char" => "a null-terminated UTF-8 string".to_owned(),
        _ if t == "void" => "a valid pointer".to_owned(),
        _ => format!("a valid `{t}` value"),
    };
    let shape = if p.static_array.is_some() {
        "an array of "
    } else if p.len.is_some() {
        "a valid pointer to an array of "
    } else if p.pointers > 0 {
        "a valid pointer to "
    } else {
        ""
    };
    format!("`{}` must be {shape}{noun}", p.name)
}

/// The FlagBits enum the specification's toolchain reads for a flags type (it looks
/// it up by name, `Flags` -> `FlagBits`, through an alias) and whether that enum has
/// a value: the toolchain writes `-zerobitmask` for a flags type without.
fn bits_by_name(model: &Model, flags: &str) -> (String, bool) {
    let mut bits = flags.replace("Flags", "FlagBits");
    if let Some(alias) = model.types.get(&bits).and_then(|t| t.alias.clone()) {
        bits = alias;
    }
    let defined = model.enum_values.get(&bits).is_some_and(|v| !v.is_empty());
    (bits, defined)
}

/// The flags types whose declaration and name disagree about their bits: the
/// registry's `requires`/`bitvalues` attribute names no enum, or another one, or one
/// whose values differ in being there from those of the enum the name leads to. The
/// derivation follows the toolchain (by name); each such type is listed, so that a
/// registry that changes the shape is seen, not silently guessed at.
pub fn bitmask_shape_notes(model: &Model) -> Vec<String> {
    let mut notes = Vec::new();
    for (name, t) in &model.types {
        if t.category != Some(Kind::Bitmask) || t.alias.is_some() {
            continue;
        }
        let (by_name, named_has) = bits_by_name(model, name);
        let declared = t.bit_values.as_deref();
        let declared_has =
            declared.is_some_and(|b| model.enum_values.get(b).is_some_and(|v| !v.is_empty()));
        if declared == Some(by_name.as_str()) || (declared.is_none() && !named_has) {
            continue;
        }
        let said = match declared {
            Some(b) if declared_has => format!("declares its bits as `{b}`"),
            Some(b) => format!("declares its bits as `{b}`, which has no value"),
            None => "declares no bits".to_owned(),
        };
        let read = if named_has {
            "which has values"
        } else {
            "which has none"
        };
        notes.push(format!(
            "`{name}` {said}; the specification's toolchain reads `{by_name}` by name, {read}: its implicit rules follow the toolchain"
        ));
    }
    notes
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn implicit_shapes() {
        assert!(is_implicit_vuid("VUID-vkCmdDraw-commandBuffer-parameter"));
        assert!(is_implicit_vuid("VUID-VkInstanceCreateInfo-pNext-pNext"));
        assert!(is_implicit_vuid("VUID-vkCmdDraw-renderpass"));
        assert!(is_implicit_vuid(
            "VUID-vkAllocateDescriptorSets-pAllocateInfo::descriptorSetCount-arraylength"
        ));
        assert!(!is_implicit_vuid("VUID-VkInstanceCreateInfo-pNext"));
        assert!(!is_implicit_vuid("VUID-vkCmdDraw-None-02690"));
        assert!(!is_implicit_vuid(
            "VUID-vkCmdDraw-renderpass-parameter-extra"
        ));
    }

    #[test]
    fn toolchain_switches_after_the_last_registry_with_the_older_rule() {
        assert!(!Toolchain::for_version("1.3.239").parent_chain);
        assert!(Toolchain::for_version("1.3.281").parent_chain);
        assert!(Toolchain::for_version("1.4.309").parent_chain);
        assert!(!Toolchain::for_version("1.4.309").suspended);
        assert!(Toolchain::for_version("1.4.330").suspended);
        assert!(Toolchain::for_version("1.5.0").device_address);
        assert!(!Toolchain::for_version("1.3.239").queuecount);
    }
}
