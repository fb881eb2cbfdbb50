#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Runs the whole test suite built with AddressSanitizer and UndefinedBehaviorSanitizer (clang,
# -O1, build-san/, built by scripts/build-sanitized.sh, shared with scripts/fuzz.sh) through
# CTest. Any sanitizer report fails the test that made it. Prints the time each half took.
#
# The random-plan stress tests run ROOMCAD_STRESS_PLANS plans (default here 100, the normal
# suite's 1000 take over 20 min under ASan); each prints the count it used.
#
# Left out here (the Release suite runs them): the slow tests that build every bundled plan
# again only to export or re-read it, or that time external readers. Under ASan they took
# 150-217 s each, 700 s of 1351 s for the slow tests (one core each), and the
# code they run is what Sh3dBuild.HomesBuild*, BuildCommand's fast tests and the stress
# tests run under the sanitizers already. Also left out: ExamplesRules.FixesOnTheBundled*,
# which validates the 304-wall arif-putra-pertama-1 twice under every rule (30 s each in
# Release; here one had not finished after 11 min of CPU); the rule tests run its code
# under the sanitizers. And BuildCommand.NefPathWritesTheSameBytesEveryRun, which builds the
# 304-wall home through Nef three times to compare the bytes (24 s in Release, 224 s here, the
# longest test of the run by far); FuzzSeeds and the random-plan tests run the Nef
# path under the sanitizers. And Sh3dBuild.GridPlanesBuildTheSolidOfTheGeneralBoolean, which
# builds every bundled home twice, with the general path's grid of planes and without, to
# compare the solids: Sh3dBuild.HomesBuild* builds them with the grid here, and the random
# plans and fuzz seeds run the general boolean.
# And RepairHomes.EachHomeKeepsTheGuarantees, which repairs every bundled home twice and
# measures each repaired solid against the one drawn (3-4 min in Release); the Repair.* tests
# run the repairs' code under the sanitizers.
# ROOMCAD_SANITIZE_ALL=1 keeps them.
# Usage: scripts/test-sanitized.sh [CTEST_REGEX]   (default: every test but those)
set -euo pipefail
cd "$(dirname "$0")/.."
start=$SECONDS
bash scripts/build-sanitized.sh
built=$SECONDS
source scripts/sanitizer-env.sh
export ROOMCAD_STRESS_PLANS=${ROOMCAD_STRESS_PLANS:-100}
echo "test-sanitized: ROOMCAD_STRESS_PLANS=$ROOMCAD_STRESS_PLANS"
exclude="MeshExport\.(ObjOffAndPlyReadBackAsTheModel|StlIsTheModelRoundedClosedAndNeverFlat)|StlAdmesh\.|BuildCommand\.EveryExamplePlanBuildsAndChecks|IndependentReaders\.|ExamplesRules\.FixesOnTheBundled|BuildCommand\.NefPathWritesTheSameBytesEveryRun|Sh3dBuild\.GridPlanesBuildTheSolidOfTheGeneralBoolean|RepairHomes\."
[[ ${ROOMCAD_SANITIZE_ALL:-0} == 1 ]] && exclude=""
ctest --test-dir build-san --output-on-failure -j"$(nproc)" --timeout 1500 ${1:+-R "$1"} ${exclude:+-E "$exclude"}
echo "test-sanitized: built in $((built - start)) s, tested in $((SECONDS - built)) s"
