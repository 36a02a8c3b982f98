//! Query pools and queries: creation, results, resets, and the begin and end of each
//! query in a recording.

use super::refuse;
use crate::handles::*;
use crate::recorder::{Recorder, Scope};
use crate::state::QueryPoolRecord;
use crate::structs::*;
use crate::{Error, Handle, Result};
use ash::vk;

/// The device remembers the pool's type, size and statistics.
pub(crate) fn query_pool_created(
    device: &Device,
    pool: QueryPool,
    create_info: &QueryPoolCreateInfo<'_>,
) -> QueryPool {
    device.live().query_pool_created(
        pool.raw(),
        QueryPoolRecord {
            query_type: create_info.query_type,
            count: create_info.query_count,
            statistics: create_info.pipeline_statistics,
        },
    );
    pool
}

/// The checks of `vkGetQueryPoolResults` that keep the driver inside `data` and the
/// pool: the queries exist, and `data` holds every result at its stride.
pub(crate) fn get_query_pool_results_checks(
    device: &Device,
    query_pool: &QueryPool,
    first_query: u32,
    query_count: u32,
    data: &[u8],
    stride: vk::DeviceSize,
    flags: vk::QueryResultFlags,
) -> Result<()> {
    let pool = device
        .live()
        .query_pool(query_pool.raw())
        .ok_or(Error::Misuse(
            "the query pool was not created through the wrappers",
        ))?;
    if first_query >= pool.count {
        refuse("VUID-vkGetQueryPoolResults-firstQuery-00813", format!("firstQuery must be less than the number of queries in queryPool (firstQuery = {first_query}, queries = {})", pool.count))?;
    }
    if u64::from(first_query) + u64::from(query_count) > u64::from(pool.count) {
        refuse("VUID-vkGetQueryPoolResults-firstQuery-00816", format!("firstQuery plus queryCount must be at most the number of queries in queryPool (firstQuery = {first_query}, queryCount = {query_count}, queries = {})", pool.count))?;
    }
    let wide = flags.contains(vk::QueryResultFlags::TYPE_64);
    let unit: u64 = if wide { 8 } else { 4 };
    let address = data.as_ptr() as u64;
    if address % unit != 0 || stride % unit != 0 {
        let vuid = if wide {
            "VUID-vkGetQueryPoolResults-flags-00815"
        } else {
            "VUID-vkGetQueryPoolResults-flags-02827"
        };
        refuse(vuid, format!("pData and stride must be multiples of {unit} (pData = {address:#x}, stride = {stride})"))?;
    }
    if pool.query_type == vk::QueryType::TIMESTAMP && flags.contains(vk::QueryResultFlags::PARTIAL)
    {
        refuse(
            "VUID-vkGetQueryPoolResults-queryType-00818",
            "a timestamp query pool's results cannot be partial",
        )?;
    }
    let unchecked = "tuff cannot size the results of this query type; read them with get_query_pool_results_unchecked";
    let (each, needed) = results_size(&pool, query_count, stride, flags, unchecked)?;
    match needed {
        Some(needed) if needed <= data.len() as u64 => Ok(()),
        _ => refuse(
            "VUID-vkGetQueryPoolResults-dataSize-00817",
            format!("dataSize must hold every result: {query_count} queries of {each} bytes at a stride of {stride} need more than {} bytes", data.len()),
        ),
    }
}

/// A pipeline-statistics pool counts only statistics the API defines.
pub(crate) fn create_query_pool_checks(create_info: &QueryPoolCreateInfo<'_>) -> Result<()> {
    let stats = create_info.pipeline_statistics;
    let known = vk::QueryPipelineStatisticFlags::from_raw(0x7ff);
    if create_info.query_type == vk::QueryType::PIPELINE_STATISTICS && !known.contains(stats) {
        refuse(
            "VUID-VkQueryPoolCreateInfo-queryType-00792",
            format!(
                "If `queryType` is `VK_QUERY_TYPE_PIPELINE_STATISTICS`, `pipelineStatistics` \
                 must be a valid combination of VkQueryPipelineStatisticFlagBits values \
                 (`pipelineStatistics` = {:#x})",
                stats.as_raw()
            ),
        )?;
    }
    Ok(())
}

/// A reset of queries inside the pool.
pub(crate) fn cmd_reset_query_pool_range<S: Scope>(
    recorder: &Recorder<'_, S>,
    query_pool: &QueryPool,
    first_query: u32,
    query_count: u32,
) -> Result<()> {
    let Some(record) = recorder.device().live().query_pool(query_pool.raw()) else {
        return Ok(());
    };
    reset_range(
        record.count,
        (first_query, query_count),
        (
            "VUID-vkCmdResetQueryPool-firstQuery-00796",
            "VUID-vkCmdResetQueryPool-firstQuery-00797",
        ),
    )?;
    let range = u64::from(first_query)..u64::from(first_query) + u64::from(query_count);
    let pool = query_pool.raw();
    if let Some(q) = recorder
        .queries
        .iter()
        .find(|q| q.pool == pool && range.contains(&u64::from(q.query)))
    {
        refuse(
            "VUID-vkCmdResetQueryPool-None-02841",
            format!("query {} of the pool is active (begun and not ended in this recording), and the reset covers queries {range:?}", q.query),
        )?;
    }
    Ok(())
}

/// A query begins inside its pool, on a queue that can run it, while no other
/// query of its type is active, at an index that leaves room for the subpass's
/// views.
pub(crate) fn begin_query_checks<S: Scope>(
    recorder: &Recorder<'_, S>,
    query_pool: &QueryPool,
    query: u32,
    flags: vk::QueryControlFlags,
) -> Result<()> {
    not_protected(recorder, "VUID-vkCmdBeginQuery-commandBuffer-01885")?;
    let Some(record) = recorder.device().live().query_pool(query_pool.raw()) else {
        return Ok(());
    };
    if matches!(
        record.query_type,
        vk::QueryType::ACCELERATION_STRUCTURE_SIZE_KHR
            | vk::QueryType::ACCELERATION_STRUCTURE_SERIALIZATION_BOTTOM_LEVEL_POINTERS_KHR
            | vk::QueryType::ACCELERATION_STRUCTURE_COMPACTED_SIZE_KHR
            | vk::QueryType::ACCELERATION_STRUCTURE_SERIALIZATION_SIZE_KHR
    ) {
        refuse(
            "VUID-vkCmdBeginQuery-queryType-06741",
            format!(
                "a query of type {:?} is written by acceleration structure commands, never begun",
                record.query_type
            ),
        )?;
    }
    if flags.contains(vk::QueryControlFlags::PRECISE) {
        let precise = recorder
            .device()
            .live()
            .with_features(|f| f.v10.occlusion_query_precise);
        if record.query_type != vk::QueryType::OCCLUSION || precise != vk::TRUE {
            refuse(
                "VUID-vkCmdBeginQuery-queryType-00800",
                format!("flags has PRECISE, which needs an occlusion query pool (this one's type is {:?}) and the occlusionQueryPrecise feature (enabled: {})", record.query_type, precise == vk::TRUE),
            )?;
        }
    }
    if record.query_type == vk::QueryType::TIMESTAMP {
        refuse(
            "VUID-vkCmdBeginQuery-queryType-02804",
            "The `queryType` used to create `queryPool` must not be `VK_QUERY_TYPE_TIMESTAMP`",
        )?;
    }
    if query >= record.count {
        refuse(
            "VUID-vkCmdBeginQuery-query-00802",
            format!(
                "`query` must be less than the number of queries in `queryPool` (`query` = \
                 {query}, queries = {})",
                record.count
            ),
        )?;
    }
    let flags = recorder.pool_queue_flags();
    let graphics_stats = vk::QueryPipelineStatisticFlags::from_raw(0x3ff);
    let compute_stats = vk::QueryPipelineStatisticFlags::COMPUTE_SHADER_INVOCATIONS;
    let needs = |vuid: &'static str, what: vk::QueueFlags| {
        if flags.contains(what) {
            Ok(())
        } else {
            refuse(
                vuid,
                format!("the command buffer's pool is of a queue family without {what:?} operations, which this query needs"),
            )
        }
    };
    match record.query_type {
        vk::QueryType::OCCLUSION => needs(
            "VUID-vkCmdBeginQuery-queryType-00803",
            vk::QueueFlags::GRAPHICS,
        )?,
        vk::QueryType::PIPELINE_STATISTICS => {
            if record.statistics.intersects(graphics_stats) {
                needs(
                    "VUID-vkCmdBeginQuery-queryType-00804",
                    vk::QueueFlags::GRAPHICS,
                )?;
            }
            if record.statistics.intersects(compute_stats) {
                needs(
                    "VUID-vkCmdBeginQuery-queryType-00805",
                    vk::QueueFlags::COMPUTE,
                )?;
            }
        }
        _ => {}
    }
    if let Some(q) = recorder.queries.iter().find(|q| q.ty == record.query_type) {
        refuse(
            "VUID-vkCmdBeginQuery-queryPool-01922",
            format!(
                "`queryPool` must have been created with a `queryType` that differs from that of \
                 any queries that are active within `commandBuffer` (query {} of another pool or \
                 index, of type {:?}, is active)",
                q.query, q.ty
            ),
        )?;
    }
    if let Some(i) = &recorder.instance {
        let views = i.view_mask.count_ones();
        if u64::from(query) + u64::from(views) > u64::from(record.count) {
            refuse(
                "VUID-vkCmdBeginQuery-query-00808",
                format!(
                    "the sum of `query` and the number of bits set in the current subpass's view \
                     mask must be less than or equal to the number of queries in `queryPool` \
                     (`query` = {query}, views = {views}, queries = {})",
                    record.count
                ),
            )?;
        }
    }
    recorder.query_states.check_use(
        query_pool.raw(),
        query,
        used_count(recorder),
        "VUID-vkCmdBeginQuery-None-00807",
    )
}

/// How many queries a command that begins or writes one uses: one per view of the
/// current subpass inside a multiview render pass instance, else one.
fn used_count<S: Scope>(recorder: &Recorder<'_, S>) -> u32 {
    recorder
        .instance
        .as_ref()
        .map_or(1, |i| i.view_mask.count_ones().max(1))
}

/// The recorder remembers the active query.
pub(crate) fn begin_query_done<S: Scope>(
    recorder: &mut Recorder<'_, S>,
    query_pool: &QueryPool,
    query: u32,
    flags: vk::QueryControlFlags,
) {
    let ty = recorder
        .device()
        .live()
        .query_pool(query_pool.raw())
        .map_or(vk::QueryType::from_raw(i32::MAX), |r| r.query_type);
    let subpass = recorder.instance.as_ref().map(|i| i.subpass);
    let count = used_count(recorder);
    let (live, states) = recorder.query_states_mut();
    states.used(
        live,
        query_pool.raw(),
        query,
        count,
        "VUID-vkCmdBeginQuery-None-00807",
    );
    recorder.queries.push(crate::recorder::ActiveQuery {
        pool: query_pool.raw(),
        query,
        ty,
        subpass,
        flags,
    });
    if !recorder.query_types.contains(&ty) {
        recorder.query_types.push(ty);
    }
}

/// A query ends where it was begun: active in this recording, in the same subpass,
/// or outside a render pass instance if begun outside.
pub(crate) fn end_query_checks<S: Scope>(
    recorder: &Recorder<'_, S>,
    query_pool: &QueryPool,
    query: u32,
) -> Result<()> {
    not_protected(recorder, "VUID-vkCmdEndQuery-commandBuffer-01886")?;
    if let Some(record) = recorder.device().live().query_pool(query_pool.raw()) {
        if query >= record.count {
            refuse(
                "VUID-vkCmdEndQuery-query-00810",
                format!(
                    "`query` must be less than the number of queries in `queryPool` (`query` = \
                     {query}, queries = {})",
                    record.count
                ),
            )?;
        }
        if let Some(i) = &recorder.instance {
            let views = i.view_mask.count_ones();
            if u64::from(query) + u64::from(views) > u64::from(record.count) {
                refuse(
                    "VUID-vkCmdEndQuery-query-00812",
                    format!(
                        "the sum of `query` and the number of bits set in the current subpass's \
                         view mask must be less than or equal to the number of queries in \
                         `queryPool` (`query` = {query}, views = {views}, queries = {})",
                        record.count
                    ),
                )?;
            }
        }
    }
    let Some(active) = recorder
        .queries
        .iter()
        .find(|q| q.pool == query_pool.raw() && q.query == query)
    else {
        return refuse(
            "VUID-vkCmdEndQuery-None-01923",
            format!("All queries used by the command must be active (query {query} is not)"),
        );
    };
    match (
        active.subpass,
        recorder.instance.as_ref().map(|i| i.subpass),
    ) {
        (Some(began), Some(now)) if began != now => refuse(
            "VUID-vkCmdEndQuery-None-07007",
            format!(
                "the query was begun in subpass {began} and is ended in subpass {now}; it must end \
                 in the subpass it began in"
            ),
        ),
        (None, Some(_)) => refuse(
            "VUID-vkCmdEndQuery-None-07008",
            "the query was begun outside a render pass instance, so it must be ended outside one",
        ),
        _ => Ok(()),
    }
}

/// The recorder forgets the ended query.
pub(crate) fn end_query_done<S: Scope>(
    recorder: &mut Recorder<'_, S>,
    query_pool: &QueryPool,
    query: u32,
) {
    recorder
        .queries
        .retain(|q| !(q.pool == query_pool.raw() && q.query == query));
}

/// Refuses a query command in a protected command buffer, where queries are not
/// allowed (the pool's protected flag, recorded at its creation).
fn not_protected<S: Scope>(recorder: &Recorder<'_, S>, vuid: &'static str) -> Result<()> {
    if super::pool_family(recorder).protected {
        return refuse(
            vuid,
            "a query command in a protected command buffer (one of a pool created with PROTECTED)",
        );
    }
    Ok(())
}

/// The checks of `vkCmdCopyQueryPoolResults`: the queries inside the pool and none
/// of them active in this recording, the flags the pool's type allows, and every
/// result, at its stride, inside the destination buffer.
#[allow(clippy::too_many_arguments)]
pub(crate) fn cmd_copy_query_pool_results_checks<S: Scope>(
    recorder: &Recorder<'_, S>,
    query_pool: &QueryPool,
    first_query: u32,
    query_count: u32,
    dst_buffer: &Buffer,
    dst_offset: vk::DeviceSize,
    stride: vk::DeviceSize,
    flags: vk::QueryResultFlags,
) -> Result<()> {
    let live = recorder.device().live();
    let pool = live.query_pool(query_pool.raw()).ok_or(Error::Misuse(
        "the query pool was not created through the wrappers",
    ))?;
    if first_query >= pool.count {
        refuse("VUID-vkCmdCopyQueryPoolResults-firstQuery-00820", format!("firstQuery must be less than the number of queries in queryPool (firstQuery = {first_query}, queries = {})", pool.count))?;
    }
    let end = u64::from(first_query) + u64::from(query_count);
    if end > u64::from(pool.count) {
        refuse("VUID-vkCmdCopyQueryPoolResults-firstQuery-00821", format!("firstQuery plus queryCount must be at most the number of queries in queryPool (firstQuery = {first_query}, queryCount = {query_count}, queries = {})", pool.count))?;
    }
    if pool.query_type == vk::QueryType::PERFORMANCE_QUERY_INTEL {
        refuse(
            "VUID-vkCmdCopyQueryPoolResults-queryType-02734",
            "an INTEL performance query pool's results cannot be copied",
        )?;
    }
    if pool.query_type == vk::QueryType::TIMESTAMP && flags.contains(vk::QueryResultFlags::PARTIAL)
    {
        refuse(
            "VUID-vkCmdCopyQueryPoolResults-queryType-00827",
            "a timestamp query pool's results cannot be partial",
        )?;
    }
    let raw = query_pool.raw();
    if let Some(q) = recorder
        .queries
        .iter()
        .find(|q| q.pool == raw && (u64::from(first_query)..end).contains(&u64::from(q.query)))
    {
        refuse(
            "VUID-vkCmdCopyQueryPoolResults-None-07429",
            format!(
                "query {} of the pool is active (begun and not ended in this recording)",
                q.query
            ),
        )?;
    }
    let unchecked = "tuff cannot size the results of this query type; copy them with copy_query_pool_results_unchecked";
    let (each, needed) = results_size(&pool, query_count, stride, flags, unchecked)?;
    let size = live.buffer(dst_buffer.raw()).map_or(0, |b| b.size);
    let needed = needed.and_then(|n| n.checked_add(dst_offset));
    match needed {
        Some(needed) if needed <= size => Ok(()),
        _ => refuse(
            "VUID-vkCmdCopyQueryPoolResults-dstBuffer-00824",
            format!("dstBuffer must hold every result from dstOffset {dst_offset}: {query_count} queries of {each} bytes at a stride of {stride}, in a buffer of {size} bytes"),
        ),
    }
}

/// The bytes of one query's results (its values, by the pool's type and statistics,
/// and its availability or status where `flags` ask for them, each 4 or 8 bytes),
/// and those of `count` results at `stride` (`None` past u64). A type whose results
/// tuff cannot size is refused with `unchecked`, which names the method to use.
fn results_size(
    pool: &QueryPoolRecord,
    count: u32,
    stride: vk::DeviceSize,
    flags: vk::QueryResultFlags,
    unchecked: &'static str,
) -> Result<(u64, Option<u64>)> {
    let values: u64 = match pool.query_type {
        vk::QueryType::OCCLUSION | vk::QueryType::TIMESTAMP => 1,
        vk::QueryType::PIPELINE_STATISTICS => u64::from(pool.statistics.as_raw().count_ones()),
        _ => return Err(Error::Misuse(unchecked)),
    };
    let unit: u64 = if flags.contains(vk::QueryResultFlags::TYPE_64) {
        8
    } else {
        4
    };
    let status = flags.intersects(
        vk::QueryResultFlags::WITH_AVAILABILITY | vk::QueryResultFlags::WITH_STATUS_KHR,
    );
    let each = (values + u64::from(status)) * unit;
    let all = match count {
        0 => Some(0),
        n => stride
            .checked_mul(u64::from(n - 1))
            .and_then(|s| s.checked_add(each)),
    };
    Ok((each, all))
}

/// The recording resets the queries: the commands after it may use them.
pub(crate) fn cmd_reset_query_pool_done<S: Scope>(
    recorder: &mut Recorder<'_, S>,
    query_pool: &QueryPool,
    first_query: u32,
    query_count: u32,
) {
    let (live, states) = recorder.query_states_mut();
    states.reset(live, query_pool.raw(), first_query, query_count);
}

/// The rules of a timestamp write, by version.
struct TimestampRules {
    /// The stage is one the pool's queue family supports.
    family: &'static str,
    /// The pool is a timestamp pool.
    pool_type: &'static str,
    /// The query is inside the pool.
    query: &'static str,
    /// The pool's queue family writes timestamps.
    valid_bits: &'static str,
    /// Inside a multiview render pass instance, the views' queries are inside the
    /// pool.
    views: &'static str,
    /// Every query the command uses is unavailable.
    unavailable: &'static str,
}

const WRITE_TIMESTAMP: TimestampRules = TimestampRules {
    family: "VUID-vkCmdWriteTimestamp-pipelineStage-04074",
    pool_type: "VUID-vkCmdWriteTimestamp-queryPool-01416",
    query: "VUID-vkCmdWriteTimestamp-query-04904",
    valid_bits: "VUID-vkCmdWriteTimestamp-timestampValidBits-00829",
    views: "VUID-vkCmdWriteTimestamp-query-00831",
    unavailable: "VUID-vkCmdWriteTimestamp-None-00830",
};

const WRITE_TIMESTAMP2: TimestampRules = TimestampRules {
    family: "VUID-vkCmdWriteTimestamp2-stage-03860",
    pool_type: "VUID-vkCmdWriteTimestamp2-queryPool-03861",
    query: "VUID-vkCmdWriteTimestamp2-query-04903",
    valid_bits: "VUID-vkCmdWriteTimestamp2-timestampValidBits-03863",
    views: "VUID-vkCmdWriteTimestamp2-query-03865",
    unavailable: "VUID-vkCmdWriteTimestamp2-None-03864",
};

/// The checks of `vkCmdWriteTimestamp`.
pub(crate) fn write_timestamp_checks<S: Scope>(
    recorder: &Recorder<'_, S>,
    pipeline_stage: vk::PipelineStageFlags,
    query_pool: &QueryPool,
    query: u32,
) -> Result<()> {
    if let Some(s) = super::stages::unsupported_stage(pipeline_stage, recorder.pool_queue_flags()) {
        refuse(
            WRITE_TIMESTAMP.family,
            format!(
                "pipelineStage {s:?} is not a stage of the command pool's queue family ({:?})",
                recorder.pool_queue_flags()
            ),
        )?;
    }
    timestamp_checks(recorder, query_pool, query, &WRITE_TIMESTAMP)
}

/// The checks of `vkCmdWriteTimestamp2`: one stage, of the pool's queue family,
/// and those of the first version.
pub(crate) fn write_timestamp2_checks<S: Scope>(
    recorder: &Recorder<'_, S>,
    stage: vk::PipelineStageFlags2,
    query_pool: &QueryPool,
    query: u32,
) -> Result<()> {
    if stage.as_raw().count_ones() != 1 {
        refuse(
            "VUID-vkCmdWriteTimestamp2-stage-03859",
            format!("`stage` must only include a single pipeline stage (it is {stage:?})"),
        )?;
    }
    if let Some(s) = super::stages::unsupported_stage2(stage, recorder.pool_queue_flags()) {
        refuse(
            WRITE_TIMESTAMP2.family,
            format!(
                "stage {s:?} is not a stage of the command pool's queue family ({:?})",
                recorder.pool_queue_flags()
            ),
        )?;
    }
    timestamp_checks(recorder, query_pool, query, &WRITE_TIMESTAMP2)
}

/// What both versions of a timestamp write check of the pool and the query.
fn timestamp_checks<S: Scope>(
    recorder: &Recorder<'_, S>,
    query_pool: &QueryPool,
    query: u32,
    rules: &TimestampRules,
) -> Result<()> {
    let bits = super::pool_family(recorder).timestamp_bits;
    if bits == 0 {
        refuse(
            rules.valid_bits,
            "the command pool's queue family has timestampValidBits 0: its queues write no timestamps",
        )?;
    }
    let Some(record) = recorder.device().live().query_pool(query_pool.raw()) else {
        return Ok(());
    };
    if record.query_type != vk::QueryType::TIMESTAMP {
        refuse(
            rules.pool_type,
            format!(
                "`queryPool` must have been created with a `queryType` of \
                 `VK_QUERY_TYPE_TIMESTAMP` (it is {:?})",
                record.query_type
            ),
        )?;
    }
    if query >= record.count {
        refuse(
            rules.query,
            format!(
                "`query` must be less than the number of queries in `queryPool` (`query` = \
                 {query}, queries = {})",
                record.count
            ),
        )?;
    }
    let count = used_count(recorder);
    if recorder.instance.is_some() && u64::from(query) + u64::from(count) > u64::from(record.count)
    {
        refuse(
            rules.views,
            format!(
                "the sum of `query` and the number of bits set in the current subpass's view mask \
                 must be less than or equal to the number of queries in `queryPool` (`query` = \
                 {query}, views = {count}, queries = {})",
                record.count
            ),
        )?;
    }
    recorder
        .query_states
        .check_use(query_pool.raw(), query, count, rules.unavailable)
}

/// The recording uses the timestamp's queries.
pub(crate) fn write_timestamp_done<S: Scope>(
    recorder: &mut Recorder<'_, S>,
    query_pool: &QueryPool,
    query: u32,
) {
    timestamp_written(recorder, query_pool, query, &WRITE_TIMESTAMP);
}

/// As [`write_timestamp_done`], for the second version.
pub(crate) fn write_timestamp2_done<S: Scope>(
    recorder: &mut Recorder<'_, S>,
    query_pool: &QueryPool,
    query: u32,
) {
    timestamp_written(recorder, query_pool, query, &WRITE_TIMESTAMP2);
}

fn timestamp_written<S: Scope>(
    recorder: &mut Recorder<'_, S>,
    query_pool: &QueryPool,
    query: u32,
    rules: &TimestampRules,
) {
    let count = used_count(recorder);
    let (live, states) = recorder.query_states_mut();
    states.used(live, query_pool.raw(), query, count, rules.unavailable);
}

/// Refuses secondaries that use queries the recording used since their reset.
pub(crate) fn execute_queries_checks<S: Scope>(
    recorder: &Recorder<'_, S>,
    command_buffers: &[&CommandBuffer],
) -> Result<()> {
    let mut so_far = recorder.query_states.clone();
    for cb in command_buffers {
        if let Some(theirs) = cb.uses().queries() {
            so_far.check_then(&theirs)?;
            so_far.then(&theirs);
        }
    }
    Ok(())
}

/// The recording executes the secondaries' query resets and uses.
pub(crate) fn execute_queries_done<S: Scope>(
    recorder: &mut Recorder<'_, S>,
    command_buffers: &[&CommandBuffer],
) {
    for cb in command_buffers {
        if let Some(theirs) = cb.uses().queries() {
            recorder.query_states.then(&theirs);
        }
    }
}

/// The checks of the host's `vkResetQueryPool`: the queries inside the pool.
pub(crate) fn reset_query_pool_checks(
    device: &Device,
    query_pool: &QueryPool,
    first_query: u32,
    query_count: u32,
) -> Result<()> {
    let Some(record) = device.live().query_pool(query_pool.raw()) else {
        return Ok(());
    };
    reset_range(
        record.count,
        (first_query, query_count),
        (
            "VUID-vkResetQueryPool-firstQuery-02666",
            "VUID-vkResetQueryPool-firstQuery-02667",
        ),
    )
}

/// Refuses a reset of queries `first..first + count` that starts or ends past a
/// pool of `len` queries (`vuids`: the first query's rule, the end's), on the
/// device or on the host alike.
fn reset_range(
    len: u32,
    (first, count): (u32, u32),
    vuids: (&'static str, &'static str),
) -> Result<()> {
    if first >= len {
        refuse(
            vuids.0,
            format!(
                "`firstQuery` must be less than the number of queries in `queryPool` \
                 (`firstQuery` = {first}, queries = {len})"
            ),
        )?;
    }
    if u64::from(first) + u64::from(count) > u64::from(len) {
        refuse(
            vuids.1,
            format!(
                "The sum of `firstQuery` and `queryCount` must be less than or equal to the \
                 number of queries in `queryPool` (`firstQuery` = {first}, `queryCount` = \
                 {count}, queries = {len})"
            ),
        )?;
    }
    Ok(())
}

/// Held through a host read of a pool's results, so that no host reset runs at
/// the same time (`VUID-vkResetQueryPool-firstQuery-02742`).
pub(crate) fn get_query_pool_results_hold(
    device: &Device,
) -> Result<tuff_runtime::VutexGuard<'_, ()>> {
    Ok(device.live().query_host())
}

/// Held through a host reset and its bookkeeping: no host read or other reset of
/// the device's queries runs at the same time
/// (`VUID-vkResetQueryPool-firstQuery-02742`), and no submission runs between its
/// check that no submission touching the queries may still be executing and its
/// record (the device's submission gate, taken second: a host read waiting for
/// results holds the first, and a submission it waits for needs the gate).
pub(crate) fn reset_query_pool_hold<'d>(
    device: &'d Device,
    query_pool: &QueryPool,
    first_query: u32,
    query_count: u32,
) -> Result<(
    tuff_runtime::VutexGuard<'d, ()>,
    tuff_runtime::VutexGuard<'d, ()>,
)> {
    let host = device.live().query_host();
    let gate = device.live().descriptor_gate();
    for sub in device
        .live()
        .query_submissions(query_pool.raw(), first_query, query_count)
    {
        if !sub.poll(device) {
            refuse(
                "VUID-vkResetQueryPool-firstQuery-02741",
                format!("a submission whose commands use queries {first_query}..{} of the pool may still be executing: wait for its fence first", u64::from(first_query) + u64::from(query_count)),
            )?;
        }
    }
    Ok((host, gate))
}

/// The host reset the queries: commands may use them again.
pub(crate) fn reset_query_pool_done(
    device: &Device,
    query_pool: &QueryPool,
    first_query: u32,
    query_count: u32,
) {
    if let Some(record) = device.live().query_pool(query_pool.raw()) {
        device.live().queries_reset_on_host(
            query_pool.raw(),
            record.count,
            first_query,
            query_count,
        );
    }
}
