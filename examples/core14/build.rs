//! Hands the target and host triples to the layout test, which compiles C with the
//! `cc` crate outside a build script.

fn main() {
    for key in ["TARGET", "HOST"] {
        let value = std::env::var(key).expect("cargo sets it for build scripts");
        println!("cargo:rustc-env=CORE14_{key}={value}");
    }
}
