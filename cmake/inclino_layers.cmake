# The layers of Inclino, enforced at configure time (docs/architecture.md).
#
# Every module (inclino_add_module) declares its layer with LAYER; a module may depend on modules
# of its own layer or of a lower one. From the bottom:
#
#   base     errors, fixed-point math, CRC                         base/
#   hal      the HAL interface, its MCU ports, run-time, cycles    hal/
#   driver   the SPI engines and the sensor drivers                drivers/
#   signal   pure signal processing: averaging, stillness, filters,
#            attitude, slope, calibration maths, records           firmware/signal/
#   service  procedures over drivers: calibration storage, gyro
#            autonull, end of line                                 firmware/services/
#   app      the application (EPB/ESC)                             firmware/app/
#   board    one folder per board: pins, clock, flash, memory, main boards/
#   sim      host simulation: clock, pin bus, device models, the
#            HAL's host port, rigs                                 sim/
#   tool     host libraries of the command-line tools              tools/
#   test     test fixtures and benchmark rigs                      tests/, benches/
#
# Two checks, both fatal:
#   - a module's LAYER must be the layer of the folder it is in (each top folder sets
#     INCLINO_FOLDER_LAYER; sub-folders inherit it), so a layer is never claimed by moving a line;
#   - inclino_check_layers(), called once by inclino_finalize(), fails when a module links a module
#     of a higher layer, naming both modules and both layers. tests/build/layering proves it fires.
include_guard(GLOBAL)

set(INCLINO_LAYERS base hal driver signal service app board sim tool test)
set_property(GLOBAL PROPERTY INCLINO_MODULES "")

# Rank of a layer (its index in INCLINO_LAYERS), or -1 when it is not one.
function(_inclino_layer_rank layer out)
  list(FIND INCLINO_LAYERS "${layer}" rank)
  set(${out} ${rank} PARENT_SCOPE)
endfunction()

# Called by inclino_add_module for every module, before anything else.
function(_inclino_check_module_layer name layer)
  if(NOT layer)
    message(FATAL_ERROR "module inclino_${name}: no LAYER given (one of: ${INCLINO_LAYERS})")
  endif()
  _inclino_layer_rank("${layer}" rank)
  if(rank LESS 0)
    message(FATAL_ERROR "module inclino_${name}: unknown LAYER '${layer}' (one of: ${INCLINO_LAYERS})")
  endif()
  if(NOT DEFINED INCLINO_FOLDER_LAYER)
    message(FATAL_ERROR "module inclino_${name}: ${CMAKE_CURRENT_SOURCE_DIR} is in no layer folder "
      "(no INCLINO_FOLDER_LAYER set by a parent CMakeLists.txt)")
  endif()
  if(NOT layer STREQUAL INCLINO_FOLDER_LAYER)
    message(FATAL_ERROR "module inclino_${name} declares LAYER ${layer} but lives in "
      "${CMAKE_CURRENT_SOURCE_DIR}, a folder of layer ${INCLINO_FOLDER_LAYER}")
  endif()
endfunction()

# The direct module dependencies of a target (PUBLIC, PRIVATE and INTERFACE link items that are
# modules; generator expressions and plain libraries such as m or Eigen3::Eigen are skipped).
function(_inclino_module_deps tgt out)
  get_target_property(type ${tgt} TYPE)
  set(items "")
  if(NOT type STREQUAL "INTERFACE_LIBRARY")
    get_target_property(link ${tgt} LINK_LIBRARIES)
    if(link)
      list(APPEND items ${link})
    endif()
  endif()
  get_target_property(iface ${tgt} INTERFACE_LINK_LIBRARIES)
  if(iface)
    list(APPEND items ${iface})
  endif()
  get_property(modules GLOBAL PROPERTY INCLINO_MODULES)
  set(deps "")
  foreach(item IN LISTS items)
    string(REGEX REPLACE "^\\$<LINK_ONLY:(.*)>$" "\\1" item "${item}")
    if(item IN_LIST modules)
      list(APPEND deps ${item})
    endif()
  endforeach()
  list(REMOVE_DUPLICATES deps)
  set(${out} ${deps} PARENT_SCOPE)
endfunction()

function(inclino_check_layers)
  get_property(modules GLOBAL PROPERTY INCLINO_MODULES)
  set(errors "")
  foreach(m IN LISTS modules)
    get_property(ml GLOBAL PROPERTY INCLINO_LAYER_OF_${m})
    _inclino_layer_rank(${ml} mr)
    _inclino_module_deps(${m} deps)
    foreach(d IN LISTS deps)
      get_property(dl GLOBAL PROPERTY INCLINO_LAYER_OF_${d})
      _inclino_layer_rank(${dl} dr)
      if(dr GREATER mr)
        string(APPEND errors "\n  ${m} (layer ${ml}) depends on ${d} (layer ${dl}), a higher layer")
      endif()
    endforeach()
  endforeach()
  if(errors)
    message(FATAL_ERROR "Layering violation (docs/architecture.md): a module may depend only on "
      "its own layer or lower ones (${INCLINO_LAYERS}, from the bottom):${errors}")
  endif()
endfunction()
