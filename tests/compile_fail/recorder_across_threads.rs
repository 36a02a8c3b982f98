// A recorder holds its command pool's lock, taken by the thread that began it: it
// stays on that thread, with the `multi_thread` feature or without it.
fn send(mut cb: tuff::CommandBuffer) {
    let rec = cb.begin(&tuff::CommandBufferBeginInfo::new()).unwrap();
    std::thread::scope(|s| {
        s.spawn(move || drop(rec));
    });
}

fn main() {}
