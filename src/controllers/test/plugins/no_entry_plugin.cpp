// Test library: a shared library without mechsim's entry point (some other plugin system's).
extern "C" __attribute__((visibility("default"))) int not_a_mechsim_plugin() { return 1; }
