# ctest driver: open the browser testbed with ?selftest in headless Chromium (fresh profile, no
# network services, a virtual clock so the run does not depend on the machine's speed) and read
# the verdict web/page/selftest.js writes into the page: "selftest: pass" and its lines.
# Expects CHROMIUM, HTML and PROFILE_PARENT.
#
# A page that wrote no verdict at all is opened again, up to three times: Chromium's virtual
# clock waits for the page's own tasks and fetches, not for the WebAssembly module compiling off
# the main thread, so now and then (one run in four or so, here) the budget is spent before the
# module is ready and the page is dumped untested. A verdict, pass or FAIL, is never retried.
include(${CMAKE_CURRENT_LIST_DIR}/chromium_dump.cmake)
foreach(attempt RANGE 1 3)
    pivot_chromium_dump("?selftest" 30000 dom)
    set(errors "${dom_ERRORS}")
    string(REGEX MATCH "<pre id=\"test-result\">(selftest: [^<]*)</pre>" found "${dom}")
    if(found)
        break()
    endif()
    message("attempt ${attempt}: the page was dumped before it wrote a verdict")
endforeach()
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
