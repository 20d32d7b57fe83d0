// Default options of the sanitizer runtimes, linked into every executable of a sanitizer or
// fuzz build (CMake: oceanbox_sanitizer_defaults). Any report fails the process with exit
// code 86, which no oceanbox path returns, so a test expecting 1 or 2 cannot pass on one.
// The suppression files name third-party code only (Mesa, LLVM); never ours.

extern "C" {

// Names of the runtime's hooks are fixed by the sanitizers; each is read once at start-up.
const char* __asan_default_options() {
    return "exitcode=86:check_initialization_order=1:strict_init_order=1:detect_stack_use_after_return=1:"
           "strict_string_checks=1:print_suppressions=0";
}

const char* __lsan_default_options() {
    return "exitcode=86:print_suppressions=0:suppressions=" OCEANBOX_SANITIZER_DIR "/lsan.supp";
}

const char* __ubsan_default_options() { return "exitcode=86:print_stacktrace=1:halt_on_error=1"; }

const char* __tsan_default_options() {
    return "exitcode=86:halt_on_error=0:second_deadlock_stack=1:print_suppressions=0:suppressions=" OCEANBOX_SANITIZER_DIR
           "/tsan.supp";
}

} // extern "C"
