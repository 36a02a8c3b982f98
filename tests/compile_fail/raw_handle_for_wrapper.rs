// Commands take wrappers, which prove the handle is alive; a raw handle is refused.
fn bind(device: &tuff::Device, buffer: tuff::vk::Buffer, memory: &tuff::DeviceMemory) {
    let _ = device.bind_buffer_memory(buffer, memory, 0);
}

fn main() {}
