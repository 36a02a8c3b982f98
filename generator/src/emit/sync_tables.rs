//! Emits `src/generated/sync_tables.rs`: the registry's synchronization tables
//! (`<sync>`) as the hazard tracker reads them. For each pipeline stage, the stages it
//! stands for (`ALL_TRANSFER` for `COPY`, `BLIT`, ...) and the stages logically
//! earlier and later than it in any pipeline (`<syncpipeline>`); for each access type,
//! the access types it stands for, the stages it may be used with, and whether it
//! writes. Values are numbers, each with the registry's name beside it, so the tables
//! read the same whichever ash release spells them.

use crate::model::Model;
use crate::model::SyncTables;
use crate::names::ident;
use proc_macro2::TokenStream;
use quote::quote;
use quote::ToTokens as _;
use std::collections::BTreeMap;

/// The stages the tables know, by name, with their bits.
fn stage_bits(t: &SyncTables) -> BTreeMap<&str, u64> {
    t.stages.iter().map(|s| (s.name.as_str(), s.bit)).collect()
}

/// Every real stage: those with a bit that stand for no others, less `TOP_OF_PIPE`,
/// `BOTTOM_OF_PIPE` and `ALL_COMMANDS`, which the registry lists without an
/// equivalence although they name every stage.
fn every_stage(t: &SyncTables) -> u64 {
    t.stages
        .iter()
        .filter(|s| s.equivalent.is_empty() && !meta(&s.name))
        .fold(0, |m, s| m | s.bit)
}

fn meta(name: &str) -> bool {
    name.ends_with("_TOP_OF_PIPE_BIT")
        || name.ends_with("_BOTTOM_OF_PIPE_BIT")
        || name.ends_with("_ALL_COMMANDS_BIT")
}

/// What each stage stands for, equivalences followed to real stages.
fn stands_for(t: &SyncTables) -> BTreeMap<&str, u64> {
    let bits = stage_bits(t);
    let all = every_stage(t);
    let mut out: BTreeMap<&str, u64> = BTreeMap::new();
    for s in &t.stages {
        let mut mask = 0;
        let mut todo: Vec<&str> = s.equivalent.iter().map(String::as_str).collect();
        while let Some(n) = todo.pop() {
            mask |= bits.get(n).copied().unwrap_or(0);
            if let Some(e) = t.stages.iter().find(|x| x.name == n) {
                todo.extend(e.equivalent.iter().map(String::as_str));
            }
        }
        if s.name.ends_with("_ALL_COMMANDS_BIT") {
            mask = all;
        }
        out.insert(s.name.as_str(), mask);
    }
    out
}

/// The stages logically earlier (`later == false`) or later than each real stage in
/// any pipeline, as the pipelines' ordered stages stand for them.
fn order(t: &SyncTables, later: bool) -> BTreeMap<&str, u64> {
    let bits = stage_bits(t);
    let stands = stands_for(t);
    let real = |n: &str| match stands.get(n) {
        Some(&m) if m != 0 => m,
        _ => bits.get(n).copied().unwrap_or(0),
    };
    let mut out: BTreeMap<&str, u64> = BTreeMap::new();
    for p in &t.pipelines {
        for (i, s) in p.ordered.iter().enumerate() {
            let others = if later {
                &p.ordered[i + 1..]
            } else {
                &p.ordered[..i]
            };
            let mask = others.iter().fold(0, |m, o| m | real(o));
            for (name, &bit) in &bits {
                if bit != 0 && real(s) & bit == bit {
                    *out.entry(name).or_default() |= mask;
                }
            }
        }
    }
    out
}

/// A mask as a hexadecimal literal, whose bits a reader can pick out.
fn hex(v: u64) -> TokenStream {
    format!("0x{v:x}").parse().expect("a hexadecimal literal")
}

/// The file.
pub fn emit(model: &Model) -> TokenStream {
    // Without tables (a registry before 1.3.2xx and no reference registry) the
    // tracker knows no stage and no command.
    let empty = SyncTables::default();
    let t = model.sync.as_ref().unwrap_or(&empty);
    let stands = stands_for(t);
    let earlier = order(t, false);
    let later = order(t, true);
    let bits = stage_bits(t);
    let all = every_stage(t);
    let stages = t.stages.iter().map(|s| {
        let name = &s.name;
        let bit = hex(s.bit);
        let sf = hex(stands[name.as_str()]);
        let e = hex(earlier.get(name.as_str()).copied().unwrap_or(0));
        let l = hex(later.get(name.as_str()).copied().unwrap_or(0));
        quote!(Stage { name: #name, bit: #bit, stands_for: #sf, earlier: #e, later: #l })
    });
    let access_bits: BTreeMap<&str, u64> = t
        .accesses
        .iter()
        .map(|a| (a.name.as_str(), a.bit))
        .collect();
    let accesses = t.accesses.iter().map(|a| {
        let name = &a.name;
        let bit = hex(a.bit);
        let sf = hex(a.equivalent.iter().fold(0, |m, e| {
            m | access_bits.get(e.as_str()).copied().unwrap_or(0)
        }));
        let stages = match &a.stages {
            // Every stage, for MEMORY_READ and MEMORY_WRITE.
            None => all,
            Some(list) => list.iter().fold(0, |m, n| {
                m | match stands.get(n.as_str()) {
                    Some(&x) if x != 0 => x | bits[n.as_str()],
                    _ => bits.get(n.as_str()).copied().unwrap_or(0),
                }
            }),
        };
        let stages = hex(stages);
        let write = a.name.contains("_WRITE");
        quote!(Access { name: #name, bit: #bit, stands_for: #sf, stages: #stages, write: #write })
    });
    let version = format!(
        " The synchronization tables of vk.xml {}: each stage and access type of",
        t.version
    );
    let all = hex(all);
    let facts = match model.sync {
        Some(_) => facts(model, t),
        None => Vec::new(),
    };
    let access_of = |field: &str| {
        let name = crate::plan::accesses::DESCRIPTOR_ACCESSES
            .iter()
            .find(|(f, _)| *f == field)
            .map_or("", |(_, n)| *n);
        let bit = hex(access_bits.get(name).copied().unwrap_or(0));
        let f = ident(field);
        quote!(#f: #bit)
    };
    let fields = ["uniform", "sampled", "storage_read", "storage_write"].map(access_of);
    let descriptors = quote!(DescriptorAccess { #(#fields),* });
    let shader_stages =
        crate::plan::accesses::SHADER_STAGES
            .iter()
            .filter_map(|(shader, stage)| {
                let bit = bits.get(stage)?;
                let name = shader
                    .strip_prefix("VK_SHADER_STAGE_")
                    .and_then(|n| n.strip_suffix("_BIT"))?;
                let konst = ident(name);
                let bit = hex(*bit);
                Some(quote!((ash::vk::ShaderStageFlags::#konst, #bit)))
            });
    quote! {
        #![doc = #version]
        //! synchronization2 with what the registry says of it (`<syncstage>`,
        //! `<syncaccess>`: `syncsupport`, `syncequivalent`; `<syncpipeline>`: the
        //! logical order of stages). The hazard tracker (`state/hazards.rs`) reads them.

        /// A pipeline stage of synchronization2 and what the registry says of it.
        #[derive(Clone, Copy, Debug)]
        pub(crate) struct Stage {
            /// Its name in the registry.
            pub(crate) name: &'static str,
            /// Its bit.
            pub(crate) bit: u64,
            /// The stages it stands for (`syncequivalent`, followed; every stage for
            /// `ALL_COMMANDS`), or 0.
            pub(crate) stands_for: u64,
            /// The stages logically earlier than it in some pipeline.
            pub(crate) earlier: u64,
            /// The stages logically later than it in some pipeline.
            pub(crate) later: u64,
        }

        /// An access type of synchronization2 and what the registry says of it.
        #[derive(Clone, Copy, Debug)]
        pub(crate) struct Access {
            /// Its name in the registry.
            pub(crate) name: &'static str,
            /// Its bit.
            pub(crate) bit: u64,
            /// The access types it stands for (`syncequivalent`), or 0.
            pub(crate) stands_for: u64,
            /// The stages it may be used with (`syncsupport`, equivalences followed;
            /// every stage where the registry lists none).
            pub(crate) stages: u64,
            /// Whether it writes (its name says so: `..._WRITE_BIT`).
            pub(crate) write: bool,
        }

        /// Every stage that stands for no others.
        pub(crate) const EVERY_STAGE: u64 = #all;

        /// Every `<syncstage>`.
        pub(crate) const STAGES: &[Stage] = &[#(#stages),*];

        /// Every `<syncaccess>`.
        pub(crate) const ACCESSES: &[Access] = &[#(#accesses),*];

        /// One access a command makes: a stage, an access type, and whether it writes.
        #[derive(Clone, Copy, Debug)]
        pub(crate) struct Use {
            /// The stage: one bit, or more for a command the specification can be
            /// read to run in either (a barrier naming any of them orders it).
            pub(crate) stage: u64,
            /// The access type, one bit.
            pub(crate) access: u64,
            /// Whether the access type writes.
            pub(crate) write: bool,
        }

        impl Use {
            /// No access.
            pub(crate) const NONE: Use = Use { stage: 0, access: 0, write: false };
        }

        /// What a command reads (`src`) and writes (`dst`), from the generator's
        /// reviewed table of per-command facts (`plan/accesses.rs`).
        #[derive(Clone, Copy, Debug)]
        pub(crate) struct Facts {
            /// The command's name.
            pub(crate) name: &'static str,
            /// What it reads: its source side.
            pub(crate) src: Use,
            /// What it writes: its destination side.
            pub(crate) dst: Use,
            /// A draw's reads of its vertex buffers.
            pub(crate) vertex: Use,
            /// A draw's reads of its index buffer.
            pub(crate) index: Use,
            /// An indirect command's read of its parameters.
            pub(crate) indirect: Use,
        }

        /// The access type of each way a shader reaches a descriptor, from the
        /// generator's reviewed table (`plan/accesses.rs`).
        #[derive(Clone, Copy, Debug)]
        pub(crate) struct DescriptorAccess {
            /// A uniform buffer's loads.
            pub(crate) uniform: u64,
            /// A sampled image's or uniform texel buffer's samples and fetches.
            pub(crate) sampled: u64,
            /// A storage buffer's or image's loads.
            pub(crate) storage_read: u64,
            /// A storage buffer's or image's stores.
            pub(crate) storage_write: u64,
        }

        /// How shaders reach their descriptors.
        pub(crate) const DESCRIPTORS: DescriptorAccess = #descriptors;

        /// The stage at which each shader stage reaches its descriptors.
        pub(crate) const SHADER_STAGES: &[(ash::vk::ShaderStageFlags, u64)] = &[#(#shader_stages),*];

        #(#facts)*
    }
}

/// The per-command facts of `plan::accesses`, one constant per command the emitted
/// API has.
fn facts(model: &Model, t: &SyncTables) -> Vec<TokenStream> {
    let stage = |list: &str| {
        list.split(',').fold(0, |m, n| {
            m | t.stages.iter().find(|s| s.name == n).map_or(0, |s| s.bit)
        })
    };
    let access = |n: &str| t.accesses.iter().find(|a| a.name == n).map_or(0, |a| a.bit);
    crate::plan::accesses::ROWS
        .iter()
        .filter(|r| model.emitted.contains(r.command))
        .map(|r| {
            let name = r.command;
            let konst = crate::names::ident(&crate::plan::accesses::facts_name(name));
            let cfg = crate::names::cfg_of(model, model.condition(name));
            let role = |role: &str| match r.uses.iter().find(|u| u.role == role) {
                Some(u) => {
                    let (s, a) = (hex(stage(u.stage)), hex(access(u.access)));
                    let write = u.access.contains("_WRITE");
                    quote!(Use { stage: #s, access: #a, write: #write })
                }
                None => quote!(Use::NONE),
            };
            let (src, dst) = (role("src"), role("dst"));
            let (vertex, index, indirect) = (role("vertex"), role("index"), role("indirect"));
            let said: Vec<String> = r
                .uses
                .iter()
                .map(|u| format!("`{}`: `{}` at `{}`", u.role, u.access, u.stage))
                .collect();
            let doc = match said.is_empty() {
                true => format!("`{name}`, which orders other commands' accesses."),
                false => format!("What `{name}` reads and writes: {}.", said.join("; ")),
            };
            quote! {
                #[doc = #doc]
                #cfg
                pub(crate) const #konst: Facts = Facts { name: #name, src: #src, dst: #dst, vertex: #vertex, index: #index, indirect: #indirect };
            }
        })
        .collect()
}

/// The call of the hazard tracker's function of a command, with the command's facts.
pub(super) fn call(row: &crate::plan::accesses::Accesses, by_value: bool) -> TokenStream {
    let konst = ident(&crate::plan::accesses::facts_name(row.command));
    let path = row.call.path.split("::").map(ident);
    let args = row.call.args.iter().map(|a| match *a {
        // A method that consumes its recorder lends it to the tracker.
        "self" if by_value => quote!(&mut self),
        "self" => quote!(self),
        "&facts" => quote!(&crate::sync_tables::#konst),
        a if a.chars().all(|c| c.is_alphanumeric() || c == '_') => ident(a).into_token_stream(),
        a => a
            .parse()
            .unwrap_or_else(|_| quote!(compile_error!("a hazard-tracker argument is not Rust"))),
    });
    quote!(crate::#(#path)::*(#(#args),*))
}
