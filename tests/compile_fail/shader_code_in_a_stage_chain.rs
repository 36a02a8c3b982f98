// The registry lets VkShaderModuleCreateInfo extend a pipeline stage, but shader code
// enters only through the unsafe `create_shader_module` and its shader promise.
fn main() {
    let code = [0x0723_0203u32, 0x0001_0000, 0, 1, 0];
    let mut module = tuff::ShaderModuleCreateInfo::new().code(&code);
    let _stage = tuff::PipelineShaderStageCreateInfo::new(c"main").push_next(&mut module);
}
