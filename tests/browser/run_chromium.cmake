# ctest driver: open the replay page in headless Chromium with a fresh profile and no network
# services, let it play for 10 s of virtual time, and read the status the page writes: it must
# have drawn more than one frame, and its first canvas must hold pixels other than background.
# Expects CHROMIUM, HTML and PROFILE_PARENT (where the throwaway profile goes).
if(NOT EXISTS "${HTML}")
    message(FATAL_ERROR "${HTML} was not written")
endif()

string(RANDOM LENGTH 8 suffix)
set(profile "${PROFILE_PARENT}/chromium-profile-${suffix}")
file(REMOVE_RECURSE "${profile}")
file(MAKE_DIRECTORY "${profile}")
string(REPLACE " " "%20" url "file://${HTML}")

execute_process(
    COMMAND "${CHROMIUM}" --headless --no-sandbox --disable-gpu --disable-quic --no-first-run
        --disable-background-networking --disable-component-update --disable-sync
        "--user-data-dir=${profile}" --virtual-time-budget=10000 --dump-dom "${url}"
    RESULT_VARIABLE result
    OUTPUT_VARIABLE dom
    ERROR_VARIABLE errors
    TIMEOUT 150)
file(REMOVE_RECURSE "${profile}")

if(NOT result EQUAL 0)
    message(FATAL_ERROR "chromium failed (${result}):\n${errors}")
endif()
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
