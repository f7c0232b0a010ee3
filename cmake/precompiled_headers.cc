// The source of the target that owns rodnet's precompiled header
// (cmake/precompiled_headers.cmake); it compiles nothing of its own.
