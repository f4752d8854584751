// Test module: a shared library that is not an rtlab plugin (it exports neither entry point).
extern "C" __attribute__((visibility("default"))) int rtlab_test_not_a_plugin(void) { return 42; }
