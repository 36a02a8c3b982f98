// A draw exists only on a recorder inside a render pass instance.
fn record(mut rec: tuff::Recorder<'_, tuff::Outside>) {
    rec.draw(3, 1, 0, 0);
}

fn main() {}
