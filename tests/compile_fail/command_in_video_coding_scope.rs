// Inside a video coding scope only video commands and those Vulkan allows in both
// exist: binding a pipeline (allowed in a render pass, not in a video coding scope)
// and copying a buffer (outside both) do not compile
// (VUID-vkCmdBindPipeline-videocoding, VUID-vkCmdCopyBuffer-videocoding).
fn record(
    rec: &mut tuff::Recorder<'_, tuff::InVideoCoding>,
    pipeline: &tuff::Pipeline,
    buffer: &tuff::Buffer,
) {
    let _ = rec.bind_pipeline(tuff::vk::PipelineBindPoint::COMPUTE, pipeline);
    let _ = rec.copy_buffer(buffer, buffer, &[]);
}

fn main() {}
