//! The `tuff-gen` command line; see [`tuff_gen::cli`].

fn main() -> std::process::ExitCode {
    let code = tuff_gen::cli::run(
        std::env::args_os(),
        &mut std::io::stdout(),
        &mut std::io::stderr(),
    );
    std::process::ExitCode::from(u8::try_from(code).unwrap_or(1))
}
