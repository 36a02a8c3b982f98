// Commands are recorded through the Recorder that `CommandBuffer::begin` returns; a
// command buffer that has not begun has no recording methods.
fn record(cb: &mut tuff::CommandBuffer) {
    cb.set_line_width(1.0);
}

fn main() {}
