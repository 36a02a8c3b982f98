//! What the device records of query pools.

use super::live::Live;
use ash::vk::{self, Handle as _};

/// A live query pool's creation parameters, which `get_query_pool_results` checks
/// against.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) struct QueryPoolRecord {
    /// `VkQueryPoolCreateInfo::queryType`.
    pub query_type: vk::QueryType,
    /// `VkQueryPoolCreateInfo::queryCount`.
    pub count: u32,
    /// `VkQueryPoolCreateInfo::pipelineStatistics`.
    pub statistics: vk::QueryPipelineStatisticFlags,
}

impl Live {
    /// Records a new query pool's creation parameters.
    pub(crate) fn query_pool_created(&self, raw: vk::QueryPool, record: QueryPoolRecord) {
        self.forget_query_states(raw.as_raw());
        self.query_pools.lock().insert(raw.as_raw(), record);
    }

    /// The record of a live query pool made through the wrappers.
    pub(crate) fn query_pool(&self, raw: vk::QueryPool) -> Option<QueryPoolRecord> {
        self.query_pools.lock().get(&raw.as_raw()).copied()
    }
}
