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
    if first_query >= record.count {
        refuse(
            "VUID-vkCmdResetQueryPool-firstQuery-00796",
            format!(
                "`firstQuery` must be less than the number of queries in `queryPool` \
                 (`firstQuery` = {first_query}, queries = {})",
                record.count
            ),
        )?;
    }
    if u64::from(first_query) + u64::from(query_count) > u64::from(record.count) {
        refuse(
            "VUID-vkCmdResetQueryPool-firstQuery-00797",
            format!(
                "The sum of `firstQuery` and `queryCount` must be less than or equal to the \
                 number of queries in `queryPool` (`firstQuery` = {first_query}, `queryCount` = \
                 {query_count}, queries = {})",
                record.count
            ),
        )?;
    }
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
    Ok(())
}

/// The recorder remembers the active query.
pub(crate) fn begin_query_done<S: Scope>(
    recorder: &mut Recorder<'_, S>,
    query_pool: &QueryPool,
    query: u32,
) {
    let ty = recorder
        .device()
        .live()
        .query_pool(query_pool.raw())
        .map_or(vk::QueryType::from_raw(i32::MAX), |r| r.query_type);
    let subpass = recorder.instance.as_ref().map(|i| i.subpass);
    recorder.queries.push(crate::recorder::ActiveQuery {
        pool: query_pool.raw(),
        query,
        ty,
        subpass,
    });
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
