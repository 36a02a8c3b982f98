//! The static guarantees of the generated wrappers, as programs that must not compile
//! (trybuild compares each compiler error with the `.stderr` file beside it), and
//! programs that must compile beside them.

#[test]
fn misuse_does_not_compile() {
    let t = trybuild::TestCases::new();
    t.compile_fail("compile_fail/draw_outside_render_pass.rs");
    t.compile_fail("compile_fail/record_without_begin.rs");
    t.compile_fail("compile_fail/push_non_extending.rs");
    t.compile_fail("compile_fail/shader_code_in_a_stage_chain.rs");
    t.compile_fail("compile_fail/pushed_struct_reused.rs");
    t.compile_fail("compile_fail/outside_command_in_continuing_secondary.rs");
    t.compile_fail("compile_fail/raw_handle_for_wrapper.rs");
    t.compile_fail("compile_fail/raw_handles_for_handle_array.rs");
    t.compile_fail("compile_fail/handle_array_outlives_wrapper.rs");
    t.compile_fail("compile_fail/method_with_callers_rules_needs_unsafe.rs");
    t.compile_fail("compile_fail/command_in_video_coding_scope.rs");
    t.pass("compile_pass/commands_of_both_scopes_in_video_coding.rs");
    // trybuild builds these programs with tuff's default features, whatever this
    // crate's: Rc, so a handle cannot cross threads. With `multi_thread` wrappers
    // can, which the threaded tests of `soundness.rs` do.
    t.compile_fail("compile_fail/handle_across_threads.rs");
    // A recorder stays on the thread that began it, in either mode (`threads.rs`).
    t.compile_fail("compile_fail/recorder_across_threads.rs");
}
