# Included by the browser tests' ctest drivers: pivot_chromium_dump(QUERY BUDGET_MS DOM_VAR) opens
# the page HTML (with QUERY after it, "" for none) in headless Chromium with a fresh, throwaway
# profile (under PROFILE_PARENT) and no network services, lets it run BUDGET_MS of virtual time
# (so the run does not depend on the machine's speed), and sets DOM_VAR to the page as it then
# stands and DOM_VAR_ERRORS to what Chromium printed. Fails the test if the page was not built
# or Chromium fails. Expects CHROMIUM, HTML and PROFILE_PARENT.
function(pivot_chromium_dump query budget dom_var)
    if(NOT EXISTS "${HTML}")
        message(FATAL_ERROR "${HTML} was not built")
    endif()
    string(REPLACE " " "%20" url "file://${HTML}${query}")
    string(RANDOM LENGTH 8 suffix)
    set(profile "${PROFILE_PARENT}/chromium-profile-${suffix}")
    file(REMOVE_RECURSE "${profile}")
    file(MAKE_DIRECTORY "${profile}")
    execute_process(
        COMMAND "${CHROMIUM}" --headless --no-sandbox --disable-gpu --disable-quic --no-first-run
            --disable-background-networking --disable-component-update --disable-sync
            "--user-data-dir=${profile}" --virtual-time-budget=${budget} --dump-dom "${url}"
        RESULT_VARIABLE result
        OUTPUT_VARIABLE dom
        ERROR_VARIABLE errors
        TIMEOUT 240)
    file(REMOVE_RECURSE "${profile}")
    if(NOT result EQUAL 0)
        message(FATAL_ERROR "chromium failed (${result}):\n${errors}")
    endif()
    set(${dom_var} "${dom}" PARENT_SCOPE)
    set(${dom_var}_ERRORS "${errors}" PARENT_SCOPE)
endfunction()
