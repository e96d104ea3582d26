# Cross-target support: QEMU board for tests, firmware images, map files and size reports.
# (Filled in by the build-infrastructure work; see docs/build.md.)
include_guard(GLOBAL)

function(inclino_link_qemu_board exe)
  message(FATAL_ERROR "inclino_link_qemu_board: not implemented yet")
endfunction()

function(inclino_add_image)
endfunction()

function(inclino_cross_finalize)
endfunction()
