// With the multi_thread feature, wrappers share their state through Arc and may move
// to another thread.
fn send(buffer: tuff::Buffer) {
    std::thread::spawn(move || drop(buffer));
}

fn main() {}
