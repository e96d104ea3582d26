# fail_with_message.cmake - `cmake -DMESSAGE=<text> -P fail_with_message.cmake`: prints the text
# as it is and fails. The test a missing prerequisite turns into (cmake/inclino_data.cmake).
message(NOTICE "${MESSAGE}")
message(FATAL_ERROR "failed: a prerequisite of this test is missing (above)")
