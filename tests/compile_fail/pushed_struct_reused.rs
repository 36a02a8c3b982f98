// A struct pushed onto a chain holds that chain's pointer: it cannot be pushed onto
// another chain, or used on its own, while the first chain's borrows may have ended.
fn main() {
    let mut features = tuff::PhysicalDeviceVulkan13Features::new();
    {
        let mut vulkan12 = tuff::PhysicalDeviceVulkan12Features::new();
        let first = tuff::DeviceCreateInfo::new()
            .push_next(&mut vulkan12)
            .push_next(&mut features);
        let _ = first;
    }
    let _second = tuff::DeviceCreateInfo::new().push_next(&mut features);
}
