# SPDX-License-Identifier: GPL-2.0-or-later
# Slicer's CMake/ExternalProjectDependency.cmake (from commontk/Artichoke) gives the superbuild
# macros. The stand-in configures an extension's inner build directly (<Extension>_SUPERBUILD OFF),
# so only mark_as_superbuild, which the template calls before that choice, is given: it passes
# variables to the inner build in a superbuild and does nothing here.
function(mark_as_superbuild)
endfunction()
