// SPDX-License-Identifier: GPL-3.0-or-later
// jemalloc's options for the executables that link it (cmake/allocator.cmake), read from this
// symbol when the program starts.
//
// dirty_decay_ms:-1 keeps the pages a program frees for its next allocations instead of
// handing them back to the system over the following seconds. With the default (10 s), a
// build of the 70 x 70 grid that followed another took 332-370 ms against glibc's 198-249, its
// big arrays faulting their pages in again; kept, 182-187 ms (build_bench fast/70, build_ms,
// three runs of each in turns). The command runs briefly; `roomcad view` keeps at most the
// memory of its largest rebuild.
//
// thp:always asks the kernel for 2 MiB pages (where it lends them: transparent huge pages in
// "madvise" mode, Debian's default), so that a large plan's memory faults in 512 times fewer
// pages: `validate` of the 100,800-wall plan spent a fifth of its time in page faults, and
// took 0.59 of the time with them (farm-bench, 6 runs in turns). A process holds a few MiB
// more (the 14-wall home's build: 28 MiB at its peak instead of 20).
extern "C" {
// NOLINTNEXTLINE: the name and type jemalloc looks for
const char* malloc_conf = "dirty_decay_ms:-1,thp:always";
}
