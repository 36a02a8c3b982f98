// A method that leaves rules to its caller (an indirect draw: the draw parameters it
// reads from the buffer) is `unsafe fn`; calling it outside `unsafe` does not compile.
fn draw(rec: &mut tuff::Recorder<'_, tuff::InRenderPass>, args: &tuff::Buffer) {
    rec.draw_indirect(args, 0, 1, 16);
}

fn main() {}
