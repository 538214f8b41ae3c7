# CTest labels (tiers) for the discovered GoogleTest cases. Included by ctest after the file
# gtest_discover_tests writes (tests/CMakeLists order), so ${shadowlab_tests_TESTS} holds every
# test name. `ctest -L unit` lists the tests that need no GL context; `-L gl`, `-L golden`,
# `-L reference` (the Embree reference itself), `-L explorer` (a window under Xvfb),
# `-L real-scenes` (reads ../shared/scenes-real), `-L slow` (over 10 s in the normal build),
# `-L smoke` (the GL smoke test of scripts/test.sh --fast), `-L sweep` (every scene x preset,
# one ctest per scene: CMakeLists.txt).
#
# The unit tier is enforced, not trusted: its tests run with SHADOWLAB_TEST_TIER=unit, and
# creating a GL context there throws (app/gl/headless_context.cpp), so a GL test listed here
# by mistake fails and names itself.

# Suites that need no GL context (whole suite names, before the first '.').
set(_unit_suites
  PageAllocator QuadtreeFit Cascaded Dpds FacePartitioned LayoutChoice Lispsm LogPsm Psm Tsm
  SceneEffects FrameGraph ShadowDrawPlan ExplorerCaption Layout Params ParamDefines SceneFuzzRegressions SceneBuiltin SceneMotion
  SceneCameraPath SceneGltf SceneJson SceneShapes SceneRealGltf MeshFixups Metrics TourParse
  DeepScene ExplorerErrorPanel ExplorerLink ExplorerViews ExplorerSettings ExplorerColourKeys
  ExplorerExports ExplorerShortcuts ExplorerCamera ExplorerLight ExplorerLayout Reference DeepFit PointLight LightFaces DualParaboloid PointSeams FaceCache LightBudget VisibleFit BlurSpans IzbViews)
# Suites whose subject is the ray-traced reference (Embree).
set(_reference_suites Reference ReferenceScale ReferenceIndependent ReferenceIndependentReal ReferenceCache)
set(_golden_suites Golden)
# Suites that open the real window under Xvfb (or run the program that does).
set(_explorer_suites ExplorerSmoke TourPlayer)
# Names that read the real scenes of ../shared/scenes-real (they skip where it is absent).
set(_real_regex "Real|[Ss]ponza|/tree|/engine|\"tree\"|\"engine\"")
# Measured over 10 s in the normal build (scripts/test.sh prints every test's time); the
# every-preset sweeps on Sponza are labelled where CMakeLists.txt adds them.
set(_slow_regex "^ExplorerSmoke\\.(ShortSoak|BrokenAccumulation|RealKeyEvents|ReturnCloses)")
# (ctest's names of parameterised tests end in "  # GetParam() = ...": no '$' anchors.)
set(_smoke_regex "^Render\\.OnlyShownViewsCostAPass|^Scenes/Golden\\.RendersAsBefore/basic__(standard|pcf|pixel_correct) ")

# list(FIND) rather than if(IN_LIST): ctest reads this file in script mode, without CMP0057.
function(_in_list item list_name out)
  list(FIND ${list_name} "${item}" _at)
  if(_at EQUAL -1)
    set(${out} FALSE PARENT_SCOPE)
  else()
    set(${out} TRUE PARENT_SCOPE)
  endif()
endfunction()

foreach(_test IN LISTS shadowlab_tests_TESTS)
  string(REGEX REPLACE "^([A-Za-z0-9_]+/)?([A-Za-z0-9_]+)\\..*$" "\\2" _suite "${_test}")
  set(_labels "")
  _in_list("${_suite}" _unit_suites _is_unit)
  _in_list("${_suite}" _golden_suites _is_golden)
  _in_list("${_suite}" _explorer_suites _is_explorer)
  _in_list("${_suite}" _reference_suites _is_reference)
  if(_is_unit)
    list(APPEND _labels unit)
    set_tests_properties("${_test}" PROPERTIES ENVIRONMENT "SHADOWLAB_TEST_TIER=unit")
  elseif(_is_golden)
    list(APPEND _labels gl golden)
  elseif(_is_explorer)
    list(APPEND _labels gl explorer)
  else()
    list(APPEND _labels gl)
  endif()
  if(_is_reference)
    list(APPEND _labels reference)
  endif()
  if(_test MATCHES "${_real_regex}")
    list(APPEND _labels real-scenes)
  endif()
  if(_test MATCHES "${_slow_regex}")
    list(APPEND _labels slow)
  endif()
  if(_test MATCHES "${_smoke_regex}")
    list(APPEND _labels smoke)
  endif()
  set_tests_properties("${_test}" PROPERTIES LABELS "${_labels}")
endforeach()
