# Decode VCD files written by spi_demo with sigrok's own SPI decoder (as PulseView would) and
# check the words are the ones sent and received. Run by CTest:
#   cmake -DDEMO=<spi_demo> -DSIGROK=<sigrok-cli> -DWORKDIR=<dir> -P sigrok_vcd.cmake
foreach(case "3;16;toggle;3E00 5600 8001 FFFF 0000 1234;A5C3"
             "0;16;hold;0001 8000 7FFE BEEF;A5C3"
             "1;8;toggle;3E 56 81 FF;A5"
             "2;8;hold;00 12 C3 7E;A5")
  list(GET case 0 mode)
  list(GET case 1 bits)
  list(GET case 2 cs)
  list(GET case 3 words)
  list(GET case 4 first)
  separate_arguments(words)
  set(vcd "${WORKDIR}/sigrok_mode${mode}_${bits}.vcd")
  set(args --vcd ${vcd} --mode ${mode} --bits ${bits})
  if(cs STREQUAL "hold")
    list(APPEND args --hold)
  endif()
  execute_process(COMMAND ${DEMO} ${args} ${words} RESULT_VARIABLE rc OUTPUT_VARIABLE out)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "spi_demo failed (${rc}):\n${out}")
  endif()
  math(EXPR cpol "${mode} >> 1")
  math(EXPR cpha "${mode} & 1")
  # The loopback answers each word with the previous one, the first with ${first}.
  set(expect_miso ${first} ${words})
  list(POP_BACK expect_miso)
  foreach(dir mosi miso)
    execute_process(
      COMMAND ${SIGROK} -I vcd -i ${vcd}
              -P spi:clk=sclk:mosi=mosi:miso=miso:cs=cs0:cpol=${cpol}:cpha=${cpha}:wordsize=${bits}
              -A spi=${dir}-data
      RESULT_VARIABLE rc OUTPUT_VARIABLE got ERROR_VARIABLE err)
    if(NOT rc EQUAL 0)
      message(FATAL_ERROR "sigrok-cli failed (${rc}): ${err}")
    endif()
    string(REGEX MATCHALL "spi-1: [0-9A-Fa-f]+" lines "${got}")
    set(values "")
    foreach(l IN LISTS lines)
      string(REGEX REPLACE "spi-1: " "" h "${l}")
      math(EXPR v "0x${h}")
      list(APPEND values ${v})
    endforeach()
    if(dir STREQUAL "mosi")
      set(expect ${words})
    else()
      set(expect ${expect_miso})
    endif()
    set(expect_dec "")
    foreach(h IN LISTS expect)
      math(EXPR v "0x${h}")
      list(APPEND expect_dec ${v})
    endforeach()
    if(NOT values STREQUAL expect_dec)
      message(FATAL_ERROR "mode ${mode}/${bits}-bit ${dir}: sigrok decoded '${values}', expected '${expect_dec}'")
    endif()
    message(STATUS "mode ${mode}/${bits}-bit ${cs} ${dir}: ${got}")
  endforeach()
endforeach()
