# The station's data-flash image (calstation dflash, docs/calibration.md 4.6), run by CTest on
# the host:
#   cmake -DTOOL=<calstation> -DOBJCOPY=<objcopy> -DWORKDIR=<dir> -P dflash.cmake
# A simulated three-point calibration session, its record (fit --out), the record as S-records
# and as Intel HEX; binutils' objcopy (a tool of the field) reads both back to the same 4 096
# bytes at 0x10000000, whose first bytes are the record file's; test ftfc_dflash then loads them
# through the FTFC driver (test_ftfc DFLASH.bin RECORD.bin). Bad arguments and inputs exit 1 or
# 2 with the problem named and write no file.
if(NOT TOOL OR NOT WORKDIR OR NOT OBJCOPY)
  message(FATAL_ERROR "TOOL, OBJCOPY and WORKDIR are required (objcopy: Debian binutils)")
endif()
include(${CMAKE_CURRENT_LIST_DIR}/../cal/calstation_run.cmake)
file(REMOVE_RECURSE ${WORKDIR})
file(MAKE_DIRECTORY ${WORKDIR})
set(W ${WORKDIR})

run(simulate 0 "status=ok;command=simulate" simulate --out ${W}/station.csv)
run(fit 0 "status=ok;command=fit;record_bytes=656;format=2" fit ${W}/station.csv --out ${W}/record.bin)
run(srec 0 "status=ok;command=dflash;format=srec;address=0x10000000;bytes=4096;seq=1;family=3"
    dflash ${W}/record.bin --out ${W}/dflash.srec)
run(ihex 0 "status=ok;command=dflash;format=ihex;address=0x10000000;bytes=4096;seq=1"
    dflash ${W}/record.bin --format ihex --out ${W}/dflash.hex)

foreach(fmt srec ihex)
  set(ext ${fmt})
  if(fmt STREQUAL "ihex")
    set(ext hex)
  endif()
  execute_process(COMMAND ${OBJCOPY} -I ${fmt} -O binary ${W}/dflash.${ext} ${W}/dflash_${fmt}.bin
                  RESULT_VARIABLE rc ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(SEND_ERROR "objcopy -I ${fmt} refused dflash.${ext}: ${err}")
  endif()
  file(SIZE ${W}/dflash_${fmt}.bin size)
  if(NOT size EQUAL 4096)
    message(SEND_ERROR "dflash.${ext}: ${size} bytes, expected 4096 (two 2 KiB sectors)")
  endif()
  # the first data line's address: the D-flash base
  file(STRINGS ${W}/dflash.${ext} lines NO_HEX_CONVERSION)
  list(GET lines 1 first)
  if(fmt STREQUAL "srec" AND NOT first MATCHES "^S32510000000")
    message(SEND_ERROR "dflash.srec: first data record ${first}, expected address 0x10000000")
  endif()
  if(fmt STREQUAL "ihex")
    list(GET lines 0 first)
    if(NOT first STREQUAL ":020000041000EA")
      message(SEND_ERROR "dflash.hex: first record ${first}, expected the upper address 0x1000")
    endif()
  endif()
endforeach()
file(SHA256 ${W}/dflash_srec.bin h_srec)
file(SHA256 ${W}/dflash_ihex.bin h_ihex)
if(NOT h_srec STREQUAL h_ihex)
  message(SEND_ERROR "the S-record and Intel HEX files hold different bytes")
endif()
file(READ ${W}/record.bin rec_hex HEX)
file(READ ${W}/dflash_srec.bin slot_hex HEX LIMIT 656)
if(NOT rec_hex STREQUAL slot_hex)
  message(SEND_ERROR "slot 0 does not begin with the record file's bytes")
endif()
file(READ ${W}/dflash_srec.bin slot1_hex HEX OFFSET 2048)
string(REGEX REPLACE "f" "" rest "${slot1_hex}")
if(NOT rest STREQUAL "")
  message(SEND_ERROR "slot 1 is not erased")
endif()
file(COPY_FILE ${W}/dflash_srec.bin ${W}/dflash.bin)

# refusals: no file written
run(no_record 1 "status=error;command=dflash;error=ERR_IO" dflash ${W}/missing.bin --out ${W}/bad.srec)
file(WRITE ${W}/short.bin "not a record")
run(not_a_record 1 "status=error;command=dflash;error=ERR_FORMAT;problem=not-a-record"
    dflash ${W}/short.bin --out ${W}/bad.srec)
run(no_out 2 "status=error;command=dflash;error=usage" dflash ${W}/record.bin)
run(bad_format 2 "status=error;command=dflash" dflash ${W}/record.bin --format bin --out ${W}/bad.srec)
if(EXISTS ${W}/bad.srec)
  message(SEND_ERROR "a refused dflash wrote its output")
endif()
