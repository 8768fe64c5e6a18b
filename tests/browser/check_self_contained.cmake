# ctest driver: the replay page must open with no network at all and stay small enough to mail.
# Expects HTML (the page) and MAX_BYTES.
if(NOT EXISTS "${HTML}")
    message(FATAL_ERROR "${HTML} was not written")
endif()
file(SIZE "${HTML}" bytes)
if(bytes GREATER MAX_BYTES)
    message(FATAL_ERROR "${HTML} is ${bytes} bytes, more than ${MAX_BYTES}")
endif()
file(READ "${HTML}" page)
string(TOLOWER "${page}" page)
# Any of these would make the browser fetch something: a URL, a stylesheet or script file, a
# CSS import or url().
foreach(reference "http://" "https://" "<link" " src=" "@import" "url(")
    string(FIND "${page}" "${reference}" at)
    if(NOT at EQUAL -1)
        message(FATAL_ERROR "${HTML} refers outside itself: '${reference}' at byte ${at}")
    endif()
endforeach()
message("${HTML}: ${bytes} bytes, self-contained")
