# ctest driver: open the replay page in headless Chromium with a fresh profile and no network
# services, let it play for 10 s of virtual time, and read the status the page writes: it must
# have drawn more than one frame, and its first canvas must hold pixels other than background.
# Expects CHROMIUM, HTML and PROFILE_PARENT (where the throwaway profile goes).
include(${CMAKE_CURRENT_LIST_DIR}/chromium_dump.cmake)
pivot_chromium_dump("" 10000 dom)
set(errors "${dom_ERRORS}")
string(REGEX MATCH "<pre id=\"status\">frames-drawn: ([0-9]+); nonblank-pixels: ([0-9]+)</pre>"
    status "${dom}")
if(NOT status)
    string(SUBSTRING "${dom}" 0 2000 start)
    message(FATAL_ERROR "no status in the page chromium dumped; it began:\n${start}\n"
                        "chromium said:\n${errors}")
endif()
set(frames "${CMAKE_MATCH_1}")
set(pixels "${CMAKE_MATCH_2}")
message("${status}")
if(NOT frames GREATER 1)
    message(FATAL_ERROR "the page drew ${frames} frame(s); playback did not run")
endif()
if(NOT pixels GREATER 0)
    message(FATAL_ERROR "the first canvas is blank: nothing was drawn on it")
endif()
