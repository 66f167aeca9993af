// Sanitizer defaults for executables that start MPI (compiled into each executable through the
// CMake target isphMpiSanitizerDefaults; the sanitizer runtime only looks for these hooks in
// the executable itself). OpenMPI keeps allocations from MPI_Init, its progress thread and
// MPI_Finalize until exit, partly in plugins it has already unloaded, so LeakSanitizer would
// fail every run. Full malloc stacks let the suppressions below, which name OpenMPI's own
// functions only, recognise them; leaks anywhere else are still reported.
// Without AddressSanitizer this file compiles to nothing.
#if defined(__SANITIZE_ADDRESS__)
#define ISPH_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define ISPH_ASAN 1
#endif
#endif

#ifdef ISPH_ASAN
extern "C" {

const char* __asan_default_options() { return "fast_unwind_on_malloc=0"; }

const char* __lsan_default_options() { return "print_suppressions=0"; }

const char* __lsan_default_suppressions() {
  return "leak:ompi_mpi_init\n"
         "leak:ompi_mpi_finalize\n"
         "leak:orte_\n"
         "leak:opal_\n"
         "leak:mca_base_\n"
         "leak:event_base_loop\n";
}

}  // extern "C"
#endif
