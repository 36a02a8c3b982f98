//! The safe forms of the indirect commands; their methods are the `tuff` crate's
//! `special/indirect.rs`, over the `IndirectBuffer` of `memory/indirect.rs`.
//!
//! An indirect command reads its arguments from GPU memory when it executes, so its
//! generated method, which takes any buffer, leaves their rules to its caller and
//! stays `unsafe` ([`super::INDIRECT`]). Its safe form takes an `IndirectBuffer`,
//! whose contents only the host writes (each element checked when written) and
//! whose copy the form checks as the direct command's parameters are checked. The
//! rules here are settled by the forms alone: the report counts them as checked, and
//! the generated methods still leave them to their callers. A form is as safe as its
//! command's generated method but for these rules (`emit/helpers.rs`).

use super::How;

/// How every settlement text of a safe form begins: the generated methods' docs mark
/// these rules as the caller's, although the report counts them settled.
pub const FORM_SETTLED: &str = "by the safe forms over an `IndirectBuffer` only: ";

/// One safe form: the hand-written method, the command it records, and the rules it
/// settles that the command's generated method leaves to its caller.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Form {
    /// The method of `Recorder`, `draw_indirect_from`.
    pub method: &'static str,
    /// The command it records, `vkCmdDrawIndirect`.
    pub command: &'static str,
    /// The rules it settles.
    pub settles: &'static [(&'static str, How)],
}

const STRIDE: &str = concat!(
    "by the safe forms over an `IndirectBuffer` only: ",
    "the safe form passes the size of the argument struct as the stride (16 or 20 bytes, multiples of 4), and reads the elements of an `IndirectBuffer`"
);
const RANGE: &str = concat!(
    "by the safe forms over an `IndirectBuffer` only: ",
    "checks the range of elements the safe form reads against the elements the `IndirectBuffer` holds, kept from its creation"
);
const COUNT_RANGE: &str = concat!(
    "by the safe forms over an `IndirectBuffer` only: ",
    "checks the draws the count read from the count `IndirectBuffer` names (the host's copy, which is what the device reads) against the elements the argument buffer holds (the 1.3.239 layer does not check it: the error alone proves it)"
);
const COUNT_INSIDE: &str = concat!(
    "by the safe forms over an `IndirectBuffer` only: ",
    "checks the element the safe form reads the count from against the elements the count `IndirectBuffer` holds"
);
const COUNT_LIMIT: &str = "checked by the safe methods in every build (by the safe forms: the count the host wrote into the count `IndirectBuffer`, which is what the device reads, against maxDrawIndirectCount), but no test breaks it: lavapipe's maxDrawIndirectCount is the largest 32-bit value";
const COUNT_FEATURE: &str = concat!(
    "by the safe forms over an `IndirectBuffer` only: ",
    "checks the device enabled the drawIndirectCount feature, which it remembers"
);
const FETCH: &str = concat!(
    "by the safe forms over an `IndirectBuffer` only: ",
    "checks each draw the safe form reads from its `IndirectBuffer` (the host's copy, which is what the device reads) as a direct draw's parameters are checked: the vertices and instances it fetches lie inside the bound vertex buffers (the 1.3.239 layer does not check it: the error alone proves it)"
);
const FETCH_STRUCT: &str = concat!(
    "by the safe forms over an `IndirectBuffer` only: ",
    "checked with the command's None-02721, the same rule of each draw's arguments, whose VUID the error names"
);
const INDEXED_FETCH: &str = concat!(
    "by the safe forms over an `IndirectBuffer` only: ",
    "checks each draw the safe form reads from its `IndirectBuffer` as a direct indexed draw's parameters are checked: unless the device enabled robustBufferAccess, the vertices every index of the bound index type can name lie inside the bound vertex buffers (the 1.3.239 layer does not check it: the error alone proves it)"
);
const INDEX_RANGE: &str = concat!(
    "by the safe forms over an `IndirectBuffer` only: ",
    "checks each draw the safe form reads from its `IndirectBuffer` as a direct indexed draw's parameters are checked: the indices it reads lie inside the bound index buffer (the 1.3.239 layer does not check it: the error alone proves it)"
);
const MULTIVIEW: &str = concat!(
    "by the safe forms over an `IndirectBuffer` only: ",
    "checks each draw the safe form reads from its `IndirectBuffer`, in a render pass instance with a view mask, as a direct draw's parameters are checked: its last instance index against maxMultiviewInstanceIndex (the 1.3.239 layer does not check it: the error alone proves it)"
);
const FIRST_INSTANCE: &str = concat!(
    "by the safe forms over an `IndirectBuffer` only: ",
    "checks each draw written into an `IndirectBuffer`, when it is written, against the device's drawIndirectFirstInstance feature (the 1.3.239 layer does not check it: the error alone proves it)"
);
const GROUPS: &str = concat!(
    "by the safe forms over an `IndirectBuffer` only: ",
    "checks each dispatch written into an `IndirectBuffer`, when it is written, against the device's maxComputeWorkGroupCount (the 1.3.239 layer does not check it: the error alone proves it)"
);

/// Every safe form.
pub const FORMS: &[Form] = &[
    Form {
        method: "draw_indirect_from",
        command: "vkCmdDrawIndirect",
        settles: &[
            (
                "VUID-vkCmdDrawIndirect-drawCount-00476",
                How::Static(STRIDE),
            ),
            (
                "VUID-vkCmdDrawIndirect-drawCount-00487",
                How::Dynamic(RANGE),
            ),
            (
                "VUID-vkCmdDrawIndirect-drawCount-00488",
                How::Dynamic(RANGE),
            ),
            ("VUID-vkCmdDrawIndirect-None-02721", How::Dynamic(FETCH)),
            (
                "VUID-vkCmdDrawIndirect-maxMultiviewInstanceIndex-02688",
                How::Dynamic(MULTIVIEW),
            ),
            (
                "VUID-VkDrawIndirectCommand-None-00500",
                How::Dynamic(FETCH_STRUCT),
            ),
            (
                "VUID-VkDrawIndirectCommand-firstInstance-00501",
                How::Dynamic(FIRST_INSTANCE),
            ),
        ],
    },
    Form {
        method: "draw_indexed_indirect_from",
        command: "vkCmdDrawIndexedIndirect",
        settles: &[
            (
                "VUID-vkCmdDrawIndexedIndirect-drawCount-00528",
                How::Static(STRIDE),
            ),
            (
                "VUID-vkCmdDrawIndexedIndirect-drawCount-00539",
                How::Dynamic(RANGE),
            ),
            (
                "VUID-vkCmdDrawIndexedIndirect-drawCount-00540",
                How::Dynamic(RANGE),
            ),
            (
                "VUID-vkCmdDrawIndexedIndirect-robustBufferAccess2-07825",
                How::Dynamic(INDEX_RANGE),
            ),
            (
                "VUID-vkCmdDrawIndexedIndirect-None-02721",
                How::Dynamic(INDEXED_FETCH),
            ),
            (
                "VUID-vkCmdDrawIndexedIndirect-maxMultiviewInstanceIndex-02688",
                How::Dynamic(MULTIVIEW),
            ),
            (
                "VUID-VkDrawIndexedIndirectCommand-None-00552",
                How::Dynamic(FETCH_STRUCT),
            ),
            (
                "VUID-VkDrawIndexedIndirectCommand-firstInstance-00554",
                How::Dynamic(FIRST_INSTANCE),
            ),
        ],
    },
    Form {
        method: "draw_indirect_count_from",
        command: "vkCmdDrawIndirectCount",
        settles: &[
            (
                "VUID-vkCmdDrawIndirectCount-None-04445",
                How::Dynamic(COUNT_FEATURE),
            ),
            (
                "VUID-vkCmdDrawIndirectCount-countBufferOffset-04129",
                How::Dynamic(COUNT_INSIDE),
            ),
            (
                "VUID-vkCmdDrawIndirectCount-stride-03110",
                How::Static(STRIDE),
            ),
            (
                "VUID-vkCmdDrawIndirectCount-maxDrawCount-03111",
                How::Dynamic(RANGE),
            ),
            (
                "VUID-vkCmdDrawIndirectCount-countBuffer-02717",
                How::User(COUNT_LIMIT),
            ),
            (
                "VUID-vkCmdDrawIndirectCount-countBuffer-03121",
                How::Dynamic(COUNT_RANGE),
            ),
            (
                "VUID-vkCmdDrawIndirectCount-countBuffer-03122",
                How::Dynamic(COUNT_RANGE),
            ),
            (
                "VUID-vkCmdDrawIndirectCount-None-02721",
                How::Dynamic(FETCH),
            ),
            (
                "VUID-vkCmdDrawIndirectCount-maxMultiviewInstanceIndex-02688",
                How::Dynamic(MULTIVIEW),
            ),
            (
                "VUID-VkDrawIndirectCommand-None-00500",
                How::Dynamic(FETCH_STRUCT),
            ),
            (
                "VUID-VkDrawIndirectCommand-firstInstance-00501",
                How::Dynamic(FIRST_INSTANCE),
            ),
        ],
    },
    Form {
        method: "draw_indexed_indirect_count_from",
        command: "vkCmdDrawIndexedIndirectCount",
        settles: &[
            (
                "VUID-vkCmdDrawIndexedIndirectCount-None-04445",
                How::Dynamic(COUNT_FEATURE),
            ),
            (
                "VUID-vkCmdDrawIndexedIndirectCount-countBufferOffset-04129",
                How::Dynamic(COUNT_INSIDE),
            ),
            (
                "VUID-vkCmdDrawIndexedIndirectCount-stride-03142",
                How::Static(STRIDE),
            ),
            (
                "VUID-vkCmdDrawIndexedIndirectCount-maxDrawCount-03143",
                How::Dynamic(RANGE),
            ),
            (
                "VUID-vkCmdDrawIndexedIndirectCount-countBuffer-02717",
                How::User(COUNT_LIMIT),
            ),
            (
                "VUID-vkCmdDrawIndexedIndirectCount-countBuffer-03153",
                How::Dynamic(COUNT_RANGE),
            ),
            (
                "VUID-vkCmdDrawIndexedIndirectCount-countBuffer-03154",
                How::Dynamic(COUNT_RANGE),
            ),
            (
                "VUID-vkCmdDrawIndexedIndirectCount-robustBufferAccess2-07825",
                How::Dynamic(INDEX_RANGE),
            ),
            (
                "VUID-vkCmdDrawIndexedIndirectCount-None-02721",
                How::Dynamic(INDEXED_FETCH),
            ),
            (
                "VUID-vkCmdDrawIndexedIndirectCount-maxMultiviewInstanceIndex-02688",
                How::Dynamic(MULTIVIEW),
            ),
            (
                "VUID-VkDrawIndexedIndirectCommand-None-00552",
                How::Dynamic(FETCH_STRUCT),
            ),
            (
                "VUID-VkDrawIndexedIndirectCommand-firstInstance-00554",
                How::Dynamic(FIRST_INSTANCE),
            ),
        ],
    },
    Form {
        method: "dispatch_indirect_from",
        command: "vkCmdDispatchIndirect",
        settles: &[
            (
                "VUID-vkCmdDispatchIndirect-offset-00407",
                How::Dynamic(RANGE),
            ),
            (
                "VUID-VkDispatchIndirectCommand-x-00417",
                How::Dynamic(GROUPS),
            ),
            (
                "VUID-VkDispatchIndirectCommand-y-00418",
                How::Dynamic(GROUPS),
            ),
            (
                "VUID-VkDispatchIndirectCommand-z-00419",
                How::Dynamic(GROUPS),
            ),
        ],
    },
];

/// How the safe forms settle a rule, if one does.
pub fn settled(vuid: &str) -> Option<How> {
    FORMS
        .iter()
        .flat_map(|f| f.settles)
        .find(|(v, _)| *v == vuid)
        .map(|(_, how)| *how)
}

/// The safe form of a command, if it has one.
pub fn form(command: &str) -> Option<&'static Form> {
    FORMS.iter().find(|f| f.command == command)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_rule_two_forms_settle_is_settled_alike_and_no_row_settles_it() {
        for f in FORMS {
            assert!(
                super::super::INDIRECT.iter().any(|(c, _)| *c == f.command),
                "{} reads no indirect arguments",
                f.command
            );
            for (v, how) in f.settles {
                assert_eq!(settled(v), Some(*how), "{v} is settled two ways");
                if let How::Static(t) | How::Dynamic(t) = how {
                    assert!(t.starts_with(FORM_SETTLED), "{v}: {t}");
                }
                assert!(
                    super::super::specials().all(|s| s.settles.iter().all(|(w, _)| w != v)),
                    "{v} is settled by a special row too"
                );
            }
        }
    }
}
