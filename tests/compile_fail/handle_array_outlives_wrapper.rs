// A struct that takes one wrapper as an array of one handle borrows it: the wrapper
// cannot be dropped while the struct still points at its handle.
fn layout(device: &tuff::Device) -> tuff::Result<tuff::PipelineLayout> {
    let info = {
        let set_layout =
            device.create_descriptor_set_layout(&tuff::DescriptorSetLayoutCreateInfo::new())?;
        tuff::PipelineLayoutCreateInfo::new().set_layouts(&set_layout)
    };
    device.create_pipeline_layout(&info)
}

fn main() {}
