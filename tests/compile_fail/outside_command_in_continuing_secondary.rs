// A secondary that continues a render pass instance records inside it: a command
// allowed only outside a render pass instance does not exist on its recorder.
fn f(cb: &mut tuff::CommandBuffer, buffer: &tuff::Buffer, info: &tuff::CommandBufferBeginInfo<'_>) {
    let mut rec = cb.begin_continuing(info).unwrap();
    rec.fill_buffer(buffer, 0, 4, 0);
    rec.end().unwrap();
}

fn main() {}
