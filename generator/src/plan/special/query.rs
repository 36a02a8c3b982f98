//! The special-case rows of one concern; their functions are the `tuff` crate's
//! `special/query.rs`, and a row here calls no other (but the image-layout tracker).
//!
//! Query pools and queries: creation, results, resets, and the begin and end of each
//! query in a recording.

use super::{call, How, Special, ACTIVE_QUERIES, ACTIVE_QUERIES_ALONE, NONE, UNPROVEN_FAMILY};

const UNPROVEN_QUERIES: &str = "checked by the safe methods in every build, as the tested render-pass and query commands are (the recorder's subpass and active queries), but no test breaks it through this command yet";
const ACTIVE_RESET: &str =
    "checks the reset's queries against those the recorder has begun and not ended";
const COPIED_RESULTS: &str = "checks that every result, sized by the pool's type and statistics (kept from its creation) and the flags, lies at its stride inside the destination buffer's recorded size from dstOffset";
const ACTIVE_COPY: &str =
    "checks the copied queries against those the recorder has begun and not ended";
const UNPROVEN_INTEL: &str = "checked by the safe methods in every build (the pool's type, kept from its creation), but no test breaks it: VK_INTEL_performance_query is not one lavapipe has";
const PRECISE: &str = "checks a precise query's pool type, kept from its creation, and the device's occlusionQueryPrecise feature";
const UNPROVEN_SIZE_QUERY: &str = "checked by the safe methods in every build (the pool's type, kept from its creation), but no test breaks it: no test makes an acceleration structure query pool";
const UNPROVEN_PROTECTED: &str = "checked by the safe methods in every build (the pool's protected flag, recorded at its creation), but no test breaks it: lavapipe has no protected memory";
const QUERY_POOL: &str =
    "checks the query against the pool's type and count, kept from its creation";
const QUERY_RANGE: &str = "checks the queries against the pool's count, kept from its creation";
const STATISTICS: &str = "checks the statistics bits against those the API defines (the 1.3.239 layer does not check it: proven by the error alone)";
const UNAVAILABLE: &str = "checks each query the command uses (one per view of a multiview subpass) is reset and not used since: in the recording, at the command; and where the recording uses it before any reset of its own, at each submission, against the states the device's earlier submissions and host resets leave, in submission order (the 1.3.239 layer reports the rule as UNASSIGNED-CoreValidation-DrawState-QueryNotReset, at the submission)";
const UNAVAILABLE_SAME: &str = "checked by the safe methods in every build, by the check of the rule for every query the command uses (VUID-vkCmdWriteTimestamp-None-00830, or -03864 for the second version), whose condition includes this one and whose VUID the error names (the 1.3.239 layer reports both as UNASSIGNED-CoreValidation-DrawState-QueryNotReset)";
const UNPROVEN_TIMESTAMP_BITS: &str = "checked by the safe methods in every build (the pool's queue family's timestampValidBits, recorded at the pool's creation), but no test breaks it: lavapipe's one queue family writes 64-bit timestamps";
const UNPROVEN_TIMESTAMP_VIEWS: &str = "checked by the safe methods in every build (the current subpass's view mask, which the recorder keeps, against the pool's count, kept from its creation), as vkCmdBeginQuery's -00808 is, but no test breaks it through this command yet";
const TIMESTAMP_POOL: &str = "checks the pool's type and count, kept from its creation";
const ONE_STAGE: &str = "checks that exactly one bit of the mask is set";
const HOST_RESET_PENDING: &str = "checks the submissions that touch the pool's queries in the range (the device records each with the span of queries its recordings touch) are complete, asking their fences; the check and the reset's record hold the device's submission gate, so no submission comes between them (the 1.3.239 layer does not check it: the error alone proves it)";
const HOST_RESET_THREADS: &str = "the host's reads of results and resets of one device's queries hold one lock of the device through the call";
const QUERIES: &str = "checks the queries against the pool's count, type and statistics, kept from its creation, and that `data` holds every result at its stride";

/// The rows of this concern.
pub(super) const ROWS: &[Special] = &[
    Special {
        command: "vkCreateQueryPool",
        check: call("special::query::create_query_pool_checks", &["create_info"]),
        created: call(
            "special::query::query_pool_created",
            &["self", "created", "create_info"],
        ),
        settles: &[(
            "VUID-VkQueryPoolCreateInfo-queryType-00792",
            How::Dynamic(STATISTICS),
        )],
        ..NONE
    },
    Special {
        command: "vkCmdBeginQuery",
        check: call(
            "special::query::begin_query_checks",
            &["self", "query_pool", "query", "flags"],
        ),
        after: call(
            "special::query::begin_query_done",
            &["self", "query_pool", "query", "flags"],
        ),
        settles: &[
            (
                "VUID-vkCmdBeginQuery-queryType-02804",
                How::Dynamic(QUERY_POOL),
            ),
            ("VUID-vkCmdBeginQuery-query-00802", How::Dynamic(QUERY_POOL)),
            (
                "VUID-vkCmdBeginQuery-queryType-00803",
                How::User(UNPROVEN_FAMILY),
            ),
            (
                "VUID-vkCmdBeginQuery-queryType-00804",
                How::User(UNPROVEN_FAMILY),
            ),
            (
                "VUID-vkCmdBeginQuery-queryType-00805",
                How::User(UNPROVEN_FAMILY),
            ),
            (
                "VUID-vkCmdBeginQuery-queryPool-01922",
                How::Dynamic(ACTIVE_QUERIES),
            ),
            (
                "VUID-vkCmdBeginQuery-query-00808",
                How::User(UNPROVEN_QUERIES),
            ),
            (
                "VUID-vkCmdBeginQuery-queryType-00800",
                How::Dynamic(PRECISE),
            ),
            (
                "VUID-vkCmdBeginQuery-queryType-06741",
                How::User(UNPROVEN_SIZE_QUERY),
            ),
            (
                "VUID-vkCmdBeginQuery-commandBuffer-01885",
                How::User(UNPROVEN_PROTECTED),
            ),
            ("VUID-vkCmdBeginQuery-None-00807", How::Dynamic(UNAVAILABLE)),
        ],
        ..NONE
    },
    Special {
        command: "vkCmdEndQuery",
        check: call(
            "special::query::end_query_checks",
            &["self", "query_pool", "query"],
        ),
        after: call(
            "special::query::end_query_done",
            &["self", "query_pool", "query"],
        ),
        settles: &[
            ("VUID-vkCmdEndQuery-query-00810", How::Dynamic(QUERY_POOL)),
            (
                "VUID-vkCmdEndQuery-None-01923",
                How::Dynamic(ACTIVE_QUERIES),
            ),
            (
                "VUID-vkCmdEndQuery-None-07007",
                How::Dynamic(ACTIVE_QUERIES_ALONE),
            ),
            (
                "VUID-vkCmdEndQuery-None-07008",
                How::Dynamic(ACTIVE_QUERIES_ALONE),
            ),
            (
                "VUID-vkCmdEndQuery-query-00812",
                How::User(UNPROVEN_QUERIES),
            ),
            (
                "VUID-vkCmdEndQuery-commandBuffer-01886",
                How::User(UNPROVEN_PROTECTED),
            ),
        ],
        ..NONE
    },
    Special {
        command: "vkCmdResetQueryPool",
        check: call(
            "special::query::cmd_reset_query_pool_range",
            &["self", "query_pool", "first_query", "query_count"],
        ),
        after: call(
            "special::query::cmd_reset_query_pool_done",
            &["self", "query_pool", "first_query", "query_count"],
        ),
        settles: &[
            (
                "VUID-vkCmdResetQueryPool-firstQuery-00796",
                How::Dynamic(QUERY_RANGE),
            ),
            (
                "VUID-vkCmdResetQueryPool-firstQuery-00797",
                How::Dynamic(QUERY_RANGE),
            ),
            (
                "VUID-vkCmdResetQueryPool-None-02841",
                How::Dynamic(ACTIVE_RESET),
            ),
        ],
        ..NONE
    },
    Special {
        command: "vkCmdCopyQueryPoolResults",
        check_last: call(
            "special::query::cmd_copy_query_pool_results_checks",
            &[
                "self",
                "query_pool",
                "first_query",
                "query_count",
                "dst_buffer",
                "dst_offset",
                "stride",
                "flags",
            ],
        ),
        settles: &[
            (
                "VUID-vkCmdCopyQueryPoolResults-firstQuery-00820",
                How::Dynamic(QUERY_RANGE),
            ),
            (
                "VUID-vkCmdCopyQueryPoolResults-firstQuery-00821",
                How::Dynamic(QUERY_RANGE),
            ),
            (
                "VUID-vkCmdCopyQueryPoolResults-dstBuffer-00824",
                How::Dynamic(COPIED_RESULTS),
            ),
            (
                "VUID-vkCmdCopyQueryPoolResults-queryType-00827",
                How::Dynamic(QUERY_POOL),
            ),
            (
                "VUID-vkCmdCopyQueryPoolResults-None-07429",
                How::Dynamic(ACTIVE_COPY),
            ),
            (
                "VUID-vkCmdCopyQueryPoolResults-queryType-02734",
                How::User(UNPROVEN_INTEL),
            ),
        ],
        ..NONE
    },
    Special {
        command: "vkCmdWriteTimestamp",
        check: call(
            "special::query::write_timestamp_checks",
            &["self", "pipeline_stage", "query_pool", "query"],
        ),
        after: call(
            "special::query::write_timestamp_done",
            &["self", "query_pool", "query"],
        ),
        settles: &[
            (
                "VUID-vkCmdWriteTimestamp-pipelineStage-04074",
                How::User(UNPROVEN_FAMILY),
            ),
            (
                "VUID-vkCmdWriteTimestamp-queryPool-01416",
                How::Dynamic(TIMESTAMP_POOL),
            ),
            (
                "VUID-vkCmdWriteTimestamp-query-04904",
                How::Dynamic(TIMESTAMP_POOL),
            ),
            (
                "VUID-vkCmdWriteTimestamp-timestampValidBits-00829",
                How::User(UNPROVEN_TIMESTAMP_BITS),
            ),
            (
                "VUID-vkCmdWriteTimestamp-query-00831",
                How::User(UNPROVEN_TIMESTAMP_VIEWS),
            ),
            (
                "VUID-vkCmdWriteTimestamp-None-00830",
                How::Dynamic(UNAVAILABLE),
            ),
            (
                "VUID-vkCmdWriteTimestamp-queryPool-00828",
                How::User(UNAVAILABLE_SAME),
            ),
        ],
        ..NONE
    },
    Special {
        command: "vkCmdWriteTimestamp2",
        check: call(
            "special::query::write_timestamp2_checks",
            &["self", "stage", "query_pool", "query"],
        ),
        after: call(
            "special::query::write_timestamp2_done",
            &["self", "query_pool", "query"],
        ),
        settles: &[
            (
                "VUID-vkCmdWriteTimestamp2-stage-03859",
                How::Dynamic(ONE_STAGE),
            ),
            (
                "VUID-vkCmdWriteTimestamp2-stage-03860",
                How::User(UNPROVEN_FAMILY),
            ),
            (
                "VUID-vkCmdWriteTimestamp2-queryPool-03861",
                How::Dynamic(TIMESTAMP_POOL),
            ),
            (
                "VUID-vkCmdWriteTimestamp2-query-04903",
                How::Dynamic(TIMESTAMP_POOL),
            ),
            (
                "VUID-vkCmdWriteTimestamp2-timestampValidBits-03863",
                How::User(UNPROVEN_TIMESTAMP_BITS),
            ),
            (
                "VUID-vkCmdWriteTimestamp2-query-03865",
                How::User(UNPROVEN_TIMESTAMP_VIEWS),
            ),
            (
                "VUID-vkCmdWriteTimestamp2-None-03864",
                How::Dynamic(UNAVAILABLE),
            ),
            (
                "VUID-vkCmdWriteTimestamp2-queryPool-03862",
                How::User(UNAVAILABLE_SAME),
            ),
        ],
        ..NONE
    },
    Special {
        command: "vkResetQueryPool",
        check: call(
            "special::query::reset_query_pool_checks",
            &["self", "query_pool", "first_query", "query_count"],
        ),
        hold: call(
            "special::query::reset_query_pool_hold",
            &["self", "query_pool", "first_query", "query_count"],
        ),
        after: call(
            "special::query::reset_query_pool_done",
            &["self", "query_pool", "first_query", "query_count"],
        ),
        settles: &[
            (
                "VUID-vkResetQueryPool-firstQuery-02666",
                How::Dynamic(QUERY_RANGE),
            ),
            (
                "VUID-vkResetQueryPool-firstQuery-02667",
                How::Dynamic(QUERY_RANGE),
            ),
            (
                "VUID-vkResetQueryPool-firstQuery-02741",
                How::Dynamic(HOST_RESET_PENDING),
            ),
            (
                "VUID-vkResetQueryPool-firstQuery-02742",
                How::Static(HOST_RESET_THREADS),
            ),
        ],
        ..NONE
    },
    Special {
        command: "vkGetQueryPoolResults",
        hold: call("special::query::get_query_pool_results_hold", &["self"]),
        check: call(
            "special::query::get_query_pool_results_checks",
            &[
                "self",
                "query_pool",
                "first_query",
                "query_count",
                "data",
                "stride",
                "flags",
            ],
        ),
        settles: &[
            (
                "VUID-vkGetQueryPoolResults-firstQuery-00813",
                How::Dynamic(QUERIES),
            ),
            (
                "VUID-vkGetQueryPoolResults-firstQuery-00816",
                How::Dynamic(QUERIES),
            ),
            (
                "VUID-vkGetQueryPoolResults-flags-00815",
                How::Dynamic(QUERIES),
            ),
            (
                "VUID-vkGetQueryPoolResults-flags-02827",
                How::Dynamic(QUERIES),
            ),
            (
                "VUID-vkGetQueryPoolResults-dataSize-00817",
                How::Dynamic(QUERIES),
            ),
            (
                "VUID-vkGetQueryPoolResults-queryType-00818",
                How::Dynamic(QUERIES),
            ),
        ],
        ..NONE
    },
];
