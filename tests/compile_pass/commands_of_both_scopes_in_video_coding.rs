// Commands Vulkan allows both inside and outside a video coding scope exist on a
// recorder in one: a barrier (anywhere) and an event reset (outside render pass
// instances, in or out of video coding).
fn record(
    rec: &mut tuff::Recorder<'_, tuff::InVideoCoding>,
    event: &tuff::Event,
    dependency: &tuff::DependencyInfo<'_>,
) -> tuff::Result<()> {
    // SAFETY: never called; only its types are checked.
    unsafe {
        rec.reset_event(event, tuff::vk::PipelineStageFlags::TRANSFER);
        rec.pipeline_barrier2(dependency)
    }
}

fn main() {
    let _ = record;
}
