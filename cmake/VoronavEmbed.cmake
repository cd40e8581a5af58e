# Turns a text file into a C++ source defining `std::string_view <FUNCTION>()` in <NAMESPACE>.
# Run as a script: cmake -DINPUT=f -DOUTPUT=f.cpp -DNAMESPACE=ns -DFUNCTION=name -DHEADER=h -P ...
# The text is split into raw-string chunks of at most 16000 bytes (portable literal length).
file(READ ${INPUT} text)
string(LENGTH "${text}" n)
set(chunks "")
set(pos 0)
while(pos LESS n)
  string(SUBSTRING "${text}" ${pos} 16000 piece)
  string(APPEND chunks "    R\"voronav_embed(${piece})voronav_embed\"\n")
  math(EXPR pos "${pos} + 16000")
endwhile()
file(WRITE ${OUTPUT}.tmp
"// Generated from ${INPUT} by cmake/VoronavEmbed.cmake; do not edit.
#include \"${HEADER}\"

namespace ${NAMESPACE} {
namespace {
constexpr char kText[] =
${chunks};
}  // namespace
std::string_view ${FUNCTION}() { return {kText, sizeof(kText) - 1}; }
}  // namespace ${NAMESPACE}
")
file(COPY_FILE ${OUTPUT}.tmp ${OUTPUT} ONLY_IF_DIFFERENT)
file(REMOVE ${OUTPUT}.tmp)
