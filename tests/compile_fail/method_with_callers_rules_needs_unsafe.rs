// A method that leaves rules to its caller (a draw: the descriptors and dynamic state
// its pipeline reads) is `unsafe fn`; calling it outside `unsafe` does not compile.
fn draw(rec: &mut tuff::Recorder<'_, tuff::InRenderPass>) {
    rec.cmd_draw(3, 1, 0, 0);
}

fn main() {}
