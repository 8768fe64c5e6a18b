# ctest driver: open the browser testbed with ?selftest in headless Chromium (fresh profile, no
# network services, a virtual clock so the run does not depend on the machine's speed) and read
# the verdict web/page/selftest.js writes into the page: "selftest: pass" and its lines.
# Expects CHROMIUM, HTML and PROFILE_PARENT.
if(NOT EXISTS "${HTML}")
    message(FATAL_ERROR "${HTML} was not built (the pivot-web-site target, web/build.sh)")
endif()

string(RANDOM LENGTH 8 suffix)
set(profile "${PROFILE_PARENT}/chromium-profile-${suffix}")
file(REMOVE_RECURSE "${profile}")
file(MAKE_DIRECTORY "${profile}")
string(REPLACE " " "%20" url "file://${HTML}?selftest")

execute_process(
    COMMAND "${CHROMIUM}" --headless --no-sandbox --disable-gpu --disable-quic --no-first-run
        --disable-background-networking --disable-component-update --disable-sync
        "--user-data-dir=${profile}" --virtual-time-budget=30000 --dump-dom "${url}"
    RESULT_VARIABLE result
    OUTPUT_VARIABLE dom
    ERROR_VARIABLE errors
    TIMEOUT 240)
file(REMOVE_RECURSE "${profile}")

if(NOT result EQUAL 0)
    message(FATAL_ERROR "chromium failed (${result}):\n${errors}")
endif()
string(REGEX MATCH "<pre id=\"test-result\">(selftest: [^<]*)</pre>" found "${dom}")
if(NOT found)
    string(SUBSTRING "${dom}" 0 2000 start)
    message(FATAL_ERROR "the page wrote no self-test result; it began:\n${start}\n"
                        "chromium said:\n${errors}")
endif()
set(verdict "${CMAKE_MATCH_1}")
message("${verdict}")
if(NOT verdict MATCHES "^selftest: pass")
    message(FATAL_ERROR "the page's self-test failed")
endif()
