// Without the multi_thread feature, wrappers share their state through Rc and cannot
// move to another thread.
fn send(buffer: tuff::Buffer) {
    std::thread::spawn(move || drop(buffer));
}

fn main() {}
