//! Command plans: for every emitted command, the wrapper it becomes a method of and
//! the shape of each parameter, or why it cannot be emitted safely.

use super::Context;
use crate::model::CommandDef;
use crate::model::Kind;
use crate::model::LenEntry;
use crate::names::table;

/// How one parameter is taken and passed.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Param {
    /// The dispatchable handle: `self`.
    Dispatch,
    /// `pAllocator`: always NULL.
    Allocator,
    /// `pAllocator` of a command that creates an instance or device
    /// ([`HOST_ALLOCATED`]): the callbacks of the entry's `HostAllocator`, or NULL.
    HostAllocator,
    /// The `VkDeferredOperationKHR` a command may defer its work onto: always
    /// `VK_NULL_HANDLE`, so the command completes before the method returns. A
    /// deferred command reads its arguments and writes its outputs until the
    /// operation completes, after the method's own storage (the arrays it lays out,
    /// the handles it wraps) is gone and while nothing retains what it reads.
    NotDeferred,
    /// A count that a slice argument fills in.
    Count,
    /// A plain value.
    Value,
    /// A fixed-size array, by reference.
    Array,
    /// The handle the method is called on where it is not the dispatchable first
    /// parameter (a display, whose physical device goes first): `self`.
    Receiver,
    /// A handle, as a wrapper.
    Handle {
        /// May be null.
        optional: bool,
    },
    /// An array of handles, as a slice of wrapper references.
    HandleSlice,
    /// One struct by reference.
    StructRef {
        /// May be null.
        optional: bool,
    },
    /// One number by pointer (`pVertexOffset`): a reference to it.
    NumberRef {
        /// May be null.
        optional: bool,
    },
    /// An array of structs or values.
    Slice,
    /// An array of pointers to arrays of plain structs or numbers
    /// (`ppBuildRangeInfos`, one array per build info): a slice of slices, whose
    /// pointers the method lays out for the call (which never defers, so Vulkan
    /// reads them before it returns), where the command's special-case check reads
    /// the inner lengths.
    SliceOfSlices,
    /// Bytes sized by a count parameter.
    Bytes,
    /// Bytes Vulkan writes, sized by a count parameter.
    BytesOut,
    /// Numbers Vulkan writes, one per element of the slice whose length sets their
    /// count (`pTimestamps`, one per `pTimestampInfos`): a mutable slice the caller
    /// gives, checked to be as long.
    SliceOut,
    /// Bytes Vulkan writes, of a size no parameter gives (a device property does:
    /// the opaque capture data of descriptor buffers), taken as a mutable byte
    /// slice, where the command's special-case check compares it with that size.
    BytesOutUnsized,
    /// A `void*` whose layout another parameter describes (`pData` of an update
    /// template): passed through as a raw pointer, which makes the method `unsafe`.
    RawData,
    /// A parameter no safe shape fits (a window-system object, a pointer to
    /// pointers, an array whose length is an expression or unknown): passed through
    /// as ash's raw type, which makes the method `unsafe`.
    Raw,
    /// A window system's display connection (`Display*`, `xcb_connection_t*`,
    /// `wl_display*`), taken as a `raw_window_handle::DisplayHandle`, which is valid
    /// for as long as it is borrowed; the variant must be this window system's.
    Display(DisplayKind),
    /// A C string.
    CStr {
        /// May be null.
        optional: bool,
    },
    /// A struct Vulkan fills in, whose `pNext` chain the caller builds.
    InOut,
    /// The value the command writes, returned.
    Output,
    /// A window-system value the command writes (a Win32 `HANDLE`, a Zircon handle),
    /// returned: ash spells these as C integers or pointers, some without `Default`,
    /// so the storage starts as zero bytes.
    ForeignOutput,
    /// The handle the command creates, returned as a wrapper.
    Created,
    /// Handles the command creates, one per element of an input array.
    CreatedArray,
    /// A count and an array filled in two calls, returned as a Vec.
    Enumerated,
    /// The count of an enumeration.
    EnumCount,
}

/// A window system whose display connection a command takes, with the
/// `raw_window_handle` variant that holds it.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum DisplayKind {
    /// Xlib's `Display*`: `RawDisplayHandle::Xlib`'s `display`.
    Xlib,
    /// `xcb_connection_t*`: `RawDisplayHandle::Xcb`'s `connection`.
    Xcb,
    /// `wl_display*`: `RawDisplayHandle::Wayland`'s `display`.
    Wayland,
}

/// The display connections `raw_window_handle` carries, by the registry's type.
/// DirectFB's `IDirectFB` and QNX's types have no variant there, so they stay raw.
pub const DISPLAY_CONNECTIONS: &[(&str, DisplayKind)] = &[
    ("Display", DisplayKind::Xlib),
    ("xcb_connection_t", DisplayKind::Xcb),
    ("wl_display", DisplayKind::Wayland),
];

/// X11 protocol IDs a command takes by value (a visual, a RandR output): plain
/// numbers the X server looks up, so any value is one Vulkan may be given.
pub const X11_IDS: &[&str] = &["VisualID", "xcb_visualid_t", "RROutput"];

/// Whether the special-case check of `command` takes `param`: the shapes whose
/// lengths the registry does not give (a slice of slices, bytes sized by a device
/// property) are safe only with such a check; without one the caller passes the raw
/// pointer through an `unsafe` method.
fn sized_by_special(command: &str, param: &str) -> bool {
    super::special::special(command).is_some_and(|s| {
        s.check
            .is_some_and(|c| c.args.contains(&crate::names::param(param).as_str()))
    })
}

/// A command's plan, or why it has none.
#[derive(Debug, Clone)]
pub struct Plan {
    /// The command.
    pub name: String,
    /// The wrapper whose method it becomes.
    pub receiver: String,
    /// One shape per parameter.
    pub params: Vec<Param>,
    /// How the command moves a recorder between render-pass states, if it does.
    pub transition: Option<Transition>,
    /// Slices that share a count with an earlier slice, which sets the count: each
    /// must be as long, or (if optional) empty, when Vulkan gets NULL. Checked in
    /// every build, as a shorter one would be read past its end.
    pub same_len: Vec<SameLen>,
    /// Whether recording the command may change what a draw's or dispatch's checks
    /// read (bound objects, dynamic state, layouts, the render pass instance), so the
    /// recorder must check the next one again: every recorded command but those of
    /// [`super::special::KEEPS_DRAW_STATE`].
    pub changes_draw_state: bool,
    /// Externally synchronized member paths the wrappers cannot lock
    /// (`pNameInfo->object`): the method is `unsafe`, and its caller synchronizes them.
    pub unlocked: Vec<String>,
    /// The condition the method is compiled under
    /// ([`super::features::command_condition`]).
    pub condition: crate::model::Condition,
}

impl Plan {
    /// Whether the caller must vouch for something no check can: a parameter taken
    /// raw (`Param::Raw`, `Param::RawData`) or a member the wrappers cannot lock.
    pub fn caller_vouches(&self) -> bool {
        !self.unlocked.is_empty()
            || self
                .params
                .iter()
                .any(|p| matches!(p, Param::Raw | Param::RawData))
    }
}

/// A slice parameter sized by another's count (C names).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct SameLen {
    /// The parameter.
    pub param: String,
    /// The earlier slice whose length is the count.
    pub first: String,
    /// Whether it may be empty instead (`optional`): Vulkan gets NULL.
    pub optional: bool,
}

/// A recorder's render-pass or video-coding state, as the recorder's type parameter
/// names it.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum RecorderState {
    /// `Outside`: no render pass instance.
    Outside,
    /// `InRenderPass`: inside one begun by `vkCmdBeginRenderPass*`.
    InRenderPass,
    /// `InRendering`: inside dynamic rendering.
    InRendering,
    /// `InVideoCoding`: inside a video coding scope begun by
    /// `vkCmdBeginVideoCodingKHR`.
    InVideoCoding,
}

impl RecorderState {
    /// The type's name in the generated crate.
    pub fn type_name(self) -> &'static str {
        match self {
            RecorderState::Outside => "Outside",
            RecorderState::InRenderPass => "InRenderPass",
            RecorderState::InRendering => "InRendering",
            RecorderState::InVideoCoding => "InVideoCoding",
        }
    }
}

/// How a recorded command changes the recorder's state: the recorder's typestate
/// follows these, and a begin the checks refuse makes the matching end a no-op.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Transition {
    /// Begins a render pass instance: from `Outside` into this state.
    Begin(RecorderState),
    /// Ends one: from this state to `Outside`.
    End(RecorderState),
    /// Stays in this state (the next subpass), skipped after a refused begin.
    Within(RecorderState),
}

/// The commands that move a recorder, in one table.
const TRANSITIONS: &[(&str, Transition)] = {
    use RecorderState::*;
    use Transition::*;
    &[
        ("vkCmdBeginRenderPass", Begin(InRenderPass)),
        ("vkCmdBeginRenderPass2", Begin(InRenderPass)),
        ("vkCmdBeginRendering", Begin(InRendering)),
        ("vkCmdEndRenderPass", End(InRenderPass)),
        ("vkCmdEndRenderPass2", End(InRenderPass)),
        ("vkCmdEndRendering", End(InRendering)),
        ("vkCmdNextSubpass", Within(InRenderPass)),
        ("vkCmdNextSubpass2", Within(InRenderPass)),
        ("vkCmdBeginVideoCodingKHR", Begin(InVideoCoding)),
        ("vkCmdEndVideoCodingKHR", End(InVideoCoding)),
    ]
};

/// How `command` moves a recorder, from the table of transitions (`TRANSITIONS`).
pub fn transition(command: &str) -> Option<Transition> {
    TRANSITIONS
        .iter()
        .find(|(name, _)| *name == command)
        .map(|(_, t)| *t)
}

/// Commands that are emitted as part of something else (destroy and free run in
/// `Drop`; begin and end of a command buffer are the recorder's typestate).
pub fn handled_elsewhere(cx: &Context, name: &str) -> Option<&'static str> {
    if cx
        .model
        .handles
        .values()
        .any(|h| h.destroyed_by.iter().any(|d| d == name))
    {
        return Some("destroy");
    }
    match name {
        "vkBeginCommandBuffer" | "vkEndCommandBuffer" => Some("recorder"),
        "vkGetInstanceProcAddr" | "vkGetDeviceProcAddr" => Some("loader"),
        "vkMapMemory" | "vkUnmapMemory" | "vkMapMemory2KHR" => Some("mapping"),
        _ => None,
    }
}

/// The parent a wrapper holds: the handle it is created from (the pool for command
/// buffers and descriptor sets).
pub fn parent_of(cx: &Context, handle: &str) -> Option<String> {
    cx.model.handles.get(handle)?.parent_chain.first().cloned()
}

/// Whether a command is recorded into its command buffer (and so is a method of the
/// recorder), rather than acting on the buffer itself.
pub fn recorded(plan: &Plan) -> bool {
    plan.receiver == "VkCommandBuffer" && plan.name.starts_with("vkCmd")
}

/// The commands whose `pAllocator` is the entry's host allocator: the instance and
/// the device. Their objects are created with NULL, which leaves the choice to the
/// implementation (Mesa's drivers use the device's allocator); the wrappers' drops
/// pass the same callbacks to `vkDestroyInstance` and `vkDestroyDevice`.
pub const HOST_ALLOCATED: &[&str] = &["vkCreateInstance", "vkCreateDevice"];

/// Plan a command, or say why it cannot be emitted safely.
pub fn plan(cx: &Context, name: &str) -> Result<Plan, String> {
    let model = cx.model;
    let cmd = &model.commands[name];
    if cmd.params.is_empty() {
        return Err("no parameters".into());
    }
    let receiver = model.receiver(name).unwrap_or("Entry").to_owned();
    if table(model, name).is_none() {
        return Err("no function table".into());
    }
    let unlocked = super::sync::unsupported_members(cx, name);
    let parsed: Vec<_> = cmd.params.iter().map(|p| &p.parsed).collect();
    // Counts named by another parameter's len.
    let count_refs: Vec<(usize, String)> = parsed
        .iter()
        .enumerate()
        .filter_map(|(i, p)| match p.len.first() {
            Some(LenEntry::Reference(parts)) if parts.len() == 1 => Some((i, parts[0].clone())),
            _ => None,
        })
        .collect();
    for p in &cmd.params {
        if p.type_name != "void" && super::types::ash_type(model, &cx.facts, &p.type_name).is_none()
        {
            return Err(format!("`{}`: ash has no type `{}`", p.name, p.type_name));
        }
    }
    let mut params = Vec::new();
    for (i, (p, pp)) in cmd.params.iter().zip(&parsed).enumerate() {
        let category = model.category(&p.type_name);
        let optional = p.is_optional();
        let is_count = count_refs.iter().any(|(_, c)| c == &p.name);
        let shape = if i == 0 && receiver != "Entry" {
            Param::Dispatch
        } else if i > 0
            && p.type_name == receiver
            && p.pointers == 0
            && cmd.params[0].type_name != receiver
        {
            Param::Receiver
        } else if p.type_name == "VkAllocationCallbacks" {
            if HOST_ALLOCATED.contains(&name) {
                Param::HostAllocator
            } else {
                Param::Allocator
            }
        } else if p.type_name == "VkDeferredOperationKHR" && p.pointers == 0 && optional {
            // The optional one is the command's deferral; the operation's own
            // commands take it as a required handle.
            Param::NotDeferred
        } else if is_count && p.pointers == 0 {
            Param::Count
        } else if is_count && p.pointers == 1 && !p.is_const {
            Param::EnumCount
        } else if p.pointers == 0 {
            if p.static_array.is_some() {
                Param::Array
            } else if category == Some(Kind::Handle) {
                let required = super::special::special(name)
                    .is_some_and(|s| s.required.contains(&p.name.as_str()));
                Param::Handle {
                    optional: optional && !required,
                }
            } else if category.is_some()
                || super::shape::is_c_scalar(&p.type_name)
                || X11_IDS.contains(&p.type_name.as_str())
            {
                if matches!(category, Some(Kind::Struct | Kind::Union))
                    && cx.facts.has_lifetime(&p.type_name)
                {
                    return Err(format!("`{}` by value with pointers", p.name));
                }
                Param::Value
            } else {
                Param::Raw
            }
        } else if p.pointers == 1 && p.is_const {
            let len = pp.len.first();
            match (len, category) {
                (None, Some(Kind::Struct)) => Param::StructRef { optional },
                // One number by pointer (`pVertexOffset`): a reference, like a struct.
                (None, None) if super::shape::is_c_scalar(&p.type_name) => {
                    Param::NumberRef { optional }
                }
                (None, Some(Kind::Union)) if cx.facts.union_is_plain(model, &p.type_name) => {
                    Param::StructRef { optional }
                }
                (Some(LenEntry::NullTerminated), None) if p.type_name == "char" => {
                    Param::CStr { optional }
                }
                (Some(LenEntry::Reference(parts)), _) if parts.len() == 1 => match category {
                    Some(Kind::Handle) => Param::HandleSlice,
                    _ if p.type_name == "void" => Param::Bytes,
                    Some(Kind::Struct) | Some(Kind::Union) | Some(_) => Param::Slice,
                    None if super::shape::is_c_scalar(&p.type_name) => Param::Slice,
                    None => return Err(format!("`{}`: array of {}", p.name, p.type_name)),
                },
                (None, None) if p.type_name == "void" => Param::RawData,
                _ => Param::Raw,
            }
        } else if p.pointers == 1 && !p.is_const {
            let len = pp.len.first();
            let display = DISPLAY_CONNECTIONS
                .iter()
                .find(|(t, _)| *t == p.type_name)
                .map(|(_, k)| *k);
            let enumerated = matches!(len, Some(LenEntry::Reference(parts))
                if parts.len() == 1 && cmd.params.iter().any(|q| q.name == parts[0] && q.pointers == 1));
            match (len, category) {
                // A window-system value (a Win32 `HANDLE`, a Zircon handle) the command
                // writes is returned like any output; a pointer to a window-system
                // object (`Display*`) is one the caller passes in.
                (None, None) if super::shape::is_foreign_value(model, &p.type_name) => {
                    Param::ForeignOutput
                }
                (None, None) if display.is_some() => display.map_or(Param::Raw, Param::Display),
                (None, None)
                    if p.type_name != "void" && !super::shape::is_c_scalar(&p.type_name) =>
                {
                    Param::Raw
                }
                (Some(LenEntry::Reference(parts)), None)
                    if p.type_name == "void" && parts.len() == 1 && !enumerated =>
                {
                    Param::BytesOut
                }
                (Some(LenEntry::Reference(parts)), None)
                    if super::shape::is_c_scalar(&p.type_name)
                        && parts.len() == 1
                        && !enumerated =>
                {
                    Param::SliceOut
                }
                (None, Some(Kind::Handle)) => Param::Created,
                (_, Some(Kind::Handle)) if !enumerated => Param::CreatedArray,
                (_, _) if enumerated => Param::Enumerated,
                (None, Some(Kind::Struct)) if has_next(cx, &p.type_name) => Param::InOut,
                (None, _) if p.type_name != "void" => Param::Output,
                // No parameter gives the size (a device property does).
                (None, None) if sized_by_special(name, &p.name) => Param::BytesOutUnsized,
                _ => Param::Raw,
            }
        } else if p.pointers == 2
            && p.const_pointees == [true, true]
            && matches!(pp.len.first(), Some(LenEntry::Reference(parts)) if parts.len() == 1)
            && (super::shape::is_c_scalar(&p.type_name)
                || (category == Some(Kind::Struct)
                    && !cx.facts.is_safe(&p.type_name)
                    && !cx.facts.has_lifetime(&p.type_name)))
            // The registry gives the inner lengths only in prose (`pInfos[i].geometryCount`).
            && sized_by_special(name, &p.name)
        {
            Param::SliceOfSlices
        } else if p.pointers == 2 && p.const_pointees == [false, false] && pp.len.is_empty() {
            // A pointer the command writes (`AHardwareBuffer** pBuffer`, `void**
            // ppData` of a host mapping): returned as the raw pointer it is.
            Param::Output
        } else {
            Param::Raw
        };
        params.push(shape);
    }
    let outputs = params
        .iter()
        .filter(|p| {
            matches!(
                p,
                Param::Output
                    | Param::ForeignOutput
                    | Param::Created
                    | Param::CreatedArray
                    | Param::Enumerated
            )
        })
        .count();
    // Two arrays filled in the same two calls (a performance query's counters and
    // their descriptions) are one output, a pair of Vecs.
    let counts: Vec<Option<&str>> = cmd
        .params
        .iter()
        .zip(&params)
        .filter(|(_, s)| matches!(s, Param::Enumerated))
        .map(|(p, _)| p.parsed.len.first().and_then(LenEntry::other_param))
        .collect();
    let pair = counts.len() == 2 && counts[0].is_some() && counts[0] == counts[1];
    if outputs > 1 && !(outputs == 2 && pair) {
        return Err("several outputs".into());
    }
    if params
        .iter()
        .any(|p| matches!(p, Param::Created | Param::CreatedArray))
    {
        let created = cmd
            .params
            .last()
            .map(|p| p.type_name.clone())
            .unwrap_or_default();
        let parent = parent_of(cx, &created).unwrap_or_default();
        if !(parent == receiver
            || created == "VkInstance"
            || parent_param(cx, cmd, &parent).is_some())
        {
            return Err(format!(
                "creates a {created} whose parent {parent} it does not name"
            ));
        }
        if params.iter().any(|p| matches!(p, Param::CreatedArray)) {
            // The count lives in an input struct (`pAllocateInfo->commandBufferCount`)
            // or is the length of an input array (`createInfoCount`).
            let len = &parsed.last().map(|p| p.len.clone()).unwrap_or_default();
            if !matches!(len.first(), Some(LenEntry::Reference(_))) {
                return Err("created array without a length".into());
            }
        }
    }
    // A count whose array is taken raw would be read from nothing: an array of
    // structs the command writes into the caller's storage (not enumerated) is a
    // shape the wrappers do not take yet.
    for (i, _) in &count_refs {
        let written = cmd.params[*i].pointers == 1 && !cmd.params[*i].is_const;
        if written && matches!(params[*i], Param::Raw) {
            return Err(format!(
                "`{}`: an array of `{}` the command writes, with its length given in",
                cmd.params[*i].name, cmd.params[*i].type_name
            ));
        }
    }
    // Every slice after the first that names a count.
    let mut same_len = Vec::new();
    for (_, count) in &count_refs {
        let users: Vec<&crate::model::Field> = cmd
            .params
            .iter()
            .zip(&params)
            .filter(|(q, shape)| {
                q.parsed.len.first().and_then(LenEntry::other_param) == Some(count.as_str())
                    && matches!(
                        shape,
                        Param::Slice
                            | Param::SliceOfSlices
                            | Param::SliceOut
                            | Param::HandleSlice
                            | Param::Bytes
                            | Param::BytesOut
                    )
            })
            .map(|(q, _)| q)
            .collect();
        for q in users.iter().skip(1) {
            let entry = SameLen {
                param: q.name.clone(),
                first: users[0].name.clone(),
                optional: q.is_optional(),
            };
            if !same_len.contains(&entry) {
                same_len.push(entry);
            }
        }
    }
    let changes_draw_state = receiver == "VkCommandBuffer"
        && name.starts_with("vkCmd")
        && !super::special::KEEPS_DRAW_STATE.contains(&name);
    Ok(Plan {
        name: name.to_owned(),
        receiver,
        params,
        transition: transition(name),
        same_len,
        changes_draw_state,
        unlocked,
        condition: super::features::command_condition(model, name),
    })
}

fn has_next(cx: &Context, name: &str) -> bool {
    cx.model
        .types
        .get(name)
        .is_some_and(|t| t.members.iter().any(|m| m.name == "pNext"))
}

/// A parameter (direct or a member of a struct parameter) of type `parent`.
pub fn parent_param(
    cx: &Context,
    cmd: &CommandDef,
    parent: &str,
) -> Option<(String, Option<String>)> {
    for p in &cmd.params {
        if p.type_name == parent && p.pointers == 0 {
            return Some((p.name.clone(), None));
        }
        if let Some(t) = cx.model.types.get(&p.type_name) {
            if let Some(m) = t
                .members
                .iter()
                .find(|m| m.type_name == parent && m.pointers == 0)
            {
                return Some((p.name.clone(), Some(m.name.clone())));
            }
        }
    }
    None
}

/// Every emitted command with its plan or the reason it has none.
pub fn plans(cx: &Context) -> Vec<(String, Result<Plan, String>)> {
    cx.model
        .commands
        .values()
        .filter(|c| c.alias.is_none() && cx.model.emitted.contains(&c.name))
        .filter(|c| handled_elsewhere(cx, &c.name).is_none())
        .map(|c| (c.name.clone(), plan(cx, &c.name)))
        .collect()
}
