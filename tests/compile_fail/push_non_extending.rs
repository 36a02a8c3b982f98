// VkPhysicalDeviceVulkan13Features does not extend VkBufferCreateInfo.
fn main() {
    let mut features = tuff::PhysicalDeviceVulkan13Features::new();
    let _info = tuff::BufferCreateInfo::new().push_next(&mut features);
}
