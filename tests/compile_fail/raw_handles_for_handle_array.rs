// An array of handles is taken as wrappers (one, or a `HandleSlice`), which prove the
// handles alive; raw handles, or a slice of wrappers with no handles laid out, are not.
fn reset(device: &tuff::Device, fence: &tuff::Fence) {
    use tuff::Handle as _;
    let _ = device.reset_fences(&[fence.raw()]);
    let _ = device.reset_fences(&[fence]);
}

fn main() {}
