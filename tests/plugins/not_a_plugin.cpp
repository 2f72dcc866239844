// Test library without rotbench's entry points: a shared library, but not a plug-in.
extern "C" __attribute__((visibility("default"))) int unrelated_function() { return 42; }
