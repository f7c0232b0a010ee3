// The source of the target that owns rodnet's precompiled header
// (cmake/target_setup.cmake); it compiles nothing of its own.
