# End-to-end tests of the dtoadq command line: every kind of bad input exits non-zero with exactly
# one line naming the file and the field, and the plot commands write their files from a folder
# away from the source tree (the Python scripts are embedded). Included by tests/CMakeLists.txt.
set(CLI_TEST_DIR ${CMAKE_CURRENT_LIST_DIR})
set(CLI_SCRATCH ${CMAKE_CURRENT_BINARY_DIR}/cli_scratch)
file(MAKE_DIRECTORY ${CLI_SCRATCH})

# cli_bad_input(NAME <name> EXPECT <regex> [STDIN <file>] [ABSENT <file>] [STATUS <exit>] ARGS <dtoadq arguments...>)
# STATUS is the exit status required: 2 (every input error, the default) or 1 (no usable device).
# @PNG@ in ARGS and ABSENT stands for an output path of this test's own (tests may run in parallel).
# Runs in the source root, so presets/ and tests/cli/data/ paths are short and the messages fixed.
# EXPECT may not hold an unbalanced "[": CMake would stop splitting the argument list there.
function(cli_bad_input)
  cmake_parse_arguments(T "" "NAME;EXPECT;STDIN;ABSENT;STATUS" "ARGS" ${ARGN})
  string(REPLACE ";" "|" args "${T_ARGS}")
  string(REPLACE "@PNG@" "${CLI_SCRATCH}/${T_NAME}.png" args "${args}")
  string(REPLACE "@PNG@" "${CLI_SCRATCH}/${T_NAME}.png" T_ABSENT "${T_ABSENT}")
  set(extra)
  if(T_STDIN)
    list(APPEND extra -DSTDIN=${T_STDIN})
  endif()
  if(T_ABSENT)
    list(APPEND extra -DABSENT=${T_ABSENT})
  endif()
  if(T_STATUS)
    list(APPEND extra -DSTATUS=${T_STATUS})
  endif()
  add_test(NAME cli.${T_NAME}
           COMMAND ${CMAKE_COMMAND} -DEXE=$<TARGET_FILE:dtoadq> "-DARGS=${args}" "-DEXPECT=${T_EXPECT}" ${extra}
                   -P ${CLI_TEST_DIR}/expect_error.cmake
           WORKING_DIRECTORY ${PROJECT_SOURCE_DIR})
  set_tests_properties(cli.${T_NAME} PROPERTIES LABELS cli TIMEOUT 60)
endfunction()

set(E "^dtoadq: error: ")
set(D tests/cli/data)
set(PNG @PNG@)

# --- preset files, through `lobe` (every kind) --------------------------------------------------
set(LOBE lobe --theta-in 30 -o ${PNG} --material)
cli_bad_input(NAME lobe.missing_preset ABSENT ${PNG} EXPECT "${E}${D}/absent\\.json: cannot open preset file$"
              ARGS ${LOBE} ${D}/absent.json)
cli_bad_input(NAME lobe.malformed_json ABSENT ${PNG} EXPECT "${E}${D}/malformed\\.json: roughness: malformed JSON: .*line 2, column 1"
              ARGS ${LOBE} ${D}/malformed.json)
cli_bad_input(NAME lobe.unknown_key ABSENT ${PNG} EXPECT "${E}${D}/unknown_key\\.json: roughnes: unknown key$"
              ARGS ${LOBE} ${D}/unknown_key.json)
cli_bad_input(NAME lobe.unknown_lobe ABSENT ${PNG} EXPECT "${E}${D}/unknown_lobe\\.json: lobes\\.glosy: unknown key$"
              ARGS ${LOBE} ${D}/unknown_lobe.json)
cli_bad_input(NAME lobe.wrong_type ABSENT ${PNG} EXPECT "${E}${D}/wrong_type\\.json: roughness: expected a number, got string$"
              ARGS ${LOBE} ${D}/wrong_type.json)
cli_bad_input(NAME lobe.short_albedo ABSENT ${PNG} EXPECT "${E}${D}/short_albedo\\.json: albedo: expected an array of 3 numbers"
              ARGS ${LOBE} ${D}/short_albedo.json)
cli_bad_input(NAME lobe.out_of_range ABSENT ${PNG} EXPECT "${E}${D}/out_of_range\\.json: ior: value 4 is out of range \\[1, 3\\]$"
              ARGS ${LOBE} ${D}/out_of_range.json)
cli_bad_input(NAME lobe.negative_albedo ABSENT ${PNG} EXPECT "${E}${D}/negative_albedo\\.json: albedo\\[1\\]: value -0\\.1 is out of range"
              ARGS ${LOBE} ${D}/negative_albedo.json)
cli_bad_input(NAME lobe.unknown_model ABSENT ${PNG} EXPECT "${E}${D}/unknown_model\\.json: model: unknown value \"disney\""
              ARGS ${LOBE} ${D}/unknown_model.json)
# JSON has no NaN or infinity: nlohmann refuses both 1e999 (overflow) and NaN while parsing, before
# any key is known, so these name the file and the offending text rather than the field
cli_bad_input(NAME lobe.overflowing_number ABSENT ${PNG} EXPECT "${E}${D}/overflow\\.json: roughness: malformed JSON: number overflow parsing '1e999'$"
              ARGS ${LOBE} ${D}/overflow.json)
cli_bad_input(NAME lobe.nan_literal ABSENT ${PNG} EXPECT "${E}${D}/nan_literal\\.json: roughness: malformed JSON: .*invalid literal"
              ARGS ${LOBE} ${D}/nan_literal.json)
# a measured preset: its MERL file missing, or truncated (a header alone: 12 bytes)
cli_bad_input(NAME lobe.measured_missing ABSENT ${PNG}
              EXPECT "${E}${D}/measured_missing\\.json: measured: MERL file \"absent\\.binary\" not found \\(looked for ${D}/absent\\.binary\\)$"
              ARGS ${LOBE} ${D}/measured_missing.json)
cli_bad_input(NAME lobe.measured_truncated ABSENT ${PNG}
              EXPECT "${E}${D}/measured_truncated\\.json: measured: ${D}/header_only\\.binary: data: truncated: 12 bytes, expected 34992012$"
              ARGS ${LOBE} ${D}/measured_truncated.json)
# the second of several materials is the bad one
cli_bad_input(NAME lobe.second_material_bad ABSENT ${PNG} EXPECT "${E}${D}/unknown_key\\.json: roughnes: unknown key$"
              ARGS ${LOBE} presets/gold.json --material ${D}/unknown_key.json)

# --- lobe options ------------------------------------------------------------------------------
set(GOLD lobe --material presets/gold.json)
cli_bad_input(NAME lobe.theta_in_90 ABSENT ${PNG} EXPECT "${E}command line: --theta-in: must be in .0, 90\\) degrees$"
              ARGS ${GOLD} --theta-in 90 -o ${PNG})
cli_bad_input(NAME lobe.theta_in_negative ABSENT ${PNG} EXPECT "${E}command line: --theta-in: must be in .0, 90\\) degrees$"
              ARGS ${GOLD} --theta-in -5 -o ${PNG})
cli_bad_input(NAME lobe.theta_in_nan ABSENT ${PNG} EXPECT "${E}command line: --theta-in: must be in .0, 90\\) degrees$"
              ARGS ${GOLD} --theta-in nan -o ${PNG})
cli_bad_input(NAME lobe.phi_in_infinite ABSENT ${PNG} EXPECT "${E}command line: --phi-in: must be a finite angle in degrees$"
              ARGS ${GOLD} --theta-in 30 --phi-in inf -o ${PNG})
cli_bad_input(NAME lobe.resolution ABSENT ${PNG} EXPECT "${E}command line: --resolution: must divide 90"
              ARGS ${GOLD} --theta-in 30 --resolution 7 -o ${PNG})
cli_bad_input(NAME lobe.scale ABSENT ${PNG} EXPECT "${E}command line: --scale: expected auto, linear or log, got \"cubic\"$"
              ARGS ${GOLD} --theta-in 30 --scale cubic -o ${PNG})
cli_bad_input(NAME lobe.output_folder_missing EXPECT "${E}/nonexistent-dtoadq/lobe\\.png: -o: cannot write: folder /nonexistent-dtoadq does not exist$"
              ARGS ${GOLD} --theta-in 30 -o /nonexistent-dtoadq/lobe.png)
cli_bad_input(NAME lobe.output_is_folder EXPECT "${E}${CLI_SCRATCH}: -o: is a folder, not a file$"
              ARGS ${GOLD} --theta-in 30 -o ${CLI_SCRATCH})
cli_bad_input(NAME lobe.csv_unwritable ABSENT ${PNG} EXPECT "${E}/nonexistent-dtoadq/lobe\\.csv: --csv: cannot write"
              ARGS ${GOLD} --theta-in 30 -o ${PNG} --csv /nonexistent-dtoadq/lobe.csv)
# errors found by the option parser itself (CLI11)
cli_bad_input(NAME lobe.theta_in_not_a_number ABSENT ${PNG} EXPECT "${E}.*--theta-in.*abc"
              ARGS ${GOLD} --theta-in abc -o ${PNG})
cli_bad_input(NAME lobe.output_missing EXPECT "${E}.*--output is required"
              ARGS ${GOLD} --theta-in 30)
cli_bad_input(NAME lobe.unknown_option ABSENT ${PNG} EXPECT "${E}.*--bogus"
              ARGS ${GOLD} --theta-in 30 --bogus -o ${PNG})

# --- albedo ------------------------------------------------------------------------------------
set(ALBEDO albedo -o ${PNG} --material)
cli_bad_input(NAME albedo.missing_preset ABSENT ${PNG} EXPECT "${E}${D}/absent\\.json: cannot open preset file$"
              ARGS ${ALBEDO} ${D}/absent.json)
cli_bad_input(NAME albedo.malformed_json ABSENT ${PNG} EXPECT "${E}${D}/malformed\\.json: roughness: malformed JSON: "
              ARGS ${ALBEDO} ${D}/malformed.json)
cli_bad_input(NAME albedo.wrong_type ABSENT ${PNG} EXPECT "${E}${D}/wrong_type\\.json: roughness: expected a number, got string$"
              ARGS ${ALBEDO} ${D}/wrong_type.json)
cli_bad_input(NAME albedo.out_of_range ABSENT ${PNG} EXPECT "${E}${D}/out_of_range\\.json: ior: value 4 is out of range"
              ARGS ${ALBEDO} ${D}/out_of_range.json)
cli_bad_input(NAME albedo.overflowing_number ABSENT ${PNG} EXPECT "${E}${D}/overflow\\.json: roughness: malformed JSON: number overflow"
              ARGS ${ALBEDO} ${D}/overflow.json)
set(GOLD albedo --material presets/gold.json)
cli_bad_input(NAME albedo.strata ABSENT ${PNG} EXPECT "${E}command line: --strata: must be in \\[1, 4096\\]$"
              ARGS ${GOLD} --strata 0 -o ${PNG})
cli_bad_input(NAME albedo.angles ABSENT ${PNG} EXPECT "${E}command line: --angles: must be in \\[2, 1000\\]$"
              ARGS ${GOLD} --angles 1 -o ${PNG})
cli_bad_input(NAME albedo.compensation ABSENT ${PNG} EXPECT "${E}command line: --compensation: expected preset, on, off or both, got .sometimes.$"
              ARGS ${GOLD} --compensation sometimes -o ${PNG})
cli_bad_input(NAME albedo.compensation_type ABSENT ${PNG} EXPECT "${E}${D}/compensation_number\\.json: energy_compensation: expected true or false, got number$"
              ARGS ${ALBEDO} ${D}/compensation_number.json)
cli_bad_input(NAME albedo.phi_in_nan ABSENT ${PNG} EXPECT "${E}command line: --phi-in: must be a finite angle in degrees$"
              ARGS ${GOLD} --phi-in nan -o ${PNG})
cli_bad_input(NAME albedo.output_folder_missing EXPECT "${E}/nonexistent-dtoadq/albedo\\.png: -o: cannot write"
              ARGS ${GOLD} -o /nonexistent-dtoadq/albedo.png)
cli_bad_input(NAME albedo.csv_unwritable ABSENT ${PNG} EXPECT "${E}/nonexistent-dtoadq/albedo\\.csv: --csv: cannot write"
              ARGS ${GOLD} -o ${PNG} --csv /nonexistent-dtoadq/albedo.csv)
cli_bad_input(NAME albedo.output_missing EXPECT "${E}.*--output is required"
              ARGS ${GOLD})

# --- brdf eval / sample --------------------------------------------------------------------------
set(EVAL brdf eval --wi 30,0 --material)
cli_bad_input(NAME brdf_eval.missing_preset STDIN ${CLI_TEST_DIR}/data/bad_line.txt EXPECT "${E}${D}/absent\\.json: cannot open preset file$"
              ARGS ${EVAL} ${D}/absent.json)
cli_bad_input(NAME brdf_eval.malformed_json STDIN ${CLI_TEST_DIR}/data/bad_line.txt EXPECT "${E}${D}/malformed\\.json: roughness: malformed JSON: "
              ARGS ${EVAL} ${D}/malformed.json)
cli_bad_input(NAME brdf_eval.unknown_key STDIN ${CLI_TEST_DIR}/data/bad_line.txt EXPECT "${E}${D}/unknown_key\\.json: roughnes: unknown key$"
              ARGS ${EVAL} ${D}/unknown_key.json)
cli_bad_input(NAME brdf_eval.out_of_range STDIN ${CLI_TEST_DIR}/data/bad_line.txt EXPECT "${E}${D}/out_of_range\\.json: ior: value 4 is out of range"
              ARGS ${EVAL} ${D}/out_of_range.json)
cli_bad_input(NAME brdf_eval.bad_stdin_line STDIN ${CLI_TEST_DIR}/data/bad_line.txt
              EXPECT "${E}standard input: line 2: expected \"theta phi\" in degrees, got \"foo bar\"$"
              ARGS ${EVAL} presets/gold.json)
cli_bad_input(NAME brdf_eval.infinite_stdin_line STDIN ${CLI_TEST_DIR}/data/infinite_line.txt
              EXPECT "${E}standard input: line 3: expected \"theta phi\" in degrees, got \"10 inf\"$"
              ARGS ${EVAL} presets/gold.json)
set(EVAL_GOLD brdf eval --material presets/gold.json)
cli_bad_input(NAME brdf_eval.wi_not_a_pair STDIN ${CLI_TEST_DIR}/data/bad_line.txt EXPECT "${E}command line: --wi: expected THETA,PHI in degrees, got \"30\"$"
              ARGS ${EVAL_GOLD} --wi 30)
cli_bad_input(NAME brdf_eval.wi_out_of_range STDIN ${CLI_TEST_DIR}/data/bad_line.txt EXPECT "${E}command line: --wi: theta must be in \\[0, 180\\] degrees$"
              ARGS ${EVAL_GOLD} --wi 200,0)
cli_bad_input(NAME brdf_eval.wi_nan STDIN ${CLI_TEST_DIR}/data/bad_line.txt EXPECT "${E}command line: --wi: expected THETA,PHI in degrees, got \"nan,0\"$"
              ARGS ${EVAL_GOLD} --wi nan,0)
# found by fuzzing: 1e300 is a finite double that becomes an infinite float
cli_bad_input(NAME brdf_eval.wi_overflows_float STDIN ${CLI_TEST_DIR}/data/bad_line.txt EXPECT "${E}command line: --wi: angles must be finite$"
              ARGS ${EVAL_GOLD} --wi 0,1e300)
cli_bad_input(NAME brdf_eval.wi_missing STDIN ${CLI_TEST_DIR}/data/bad_line.txt EXPECT "${E}.*--wi is required"
              ARGS ${EVAL_GOLD})
cli_bad_input(NAME brdf_sample.missing_preset EXPECT "${E}${D}/absent\\.json: cannot open preset file$"
              ARGS brdf sample --wi 30,0 --material ${D}/absent.json)
cli_bad_input(NAME brdf_sample.wrong_type EXPECT "${E}${D}/wrong_type\\.json: roughness: expected a number, got string$"
              ARGS brdf sample --wi 30,0 --material ${D}/wrong_type.json)
cli_bad_input(NAME brdf_sample.negative_count EXPECT "${E}command line: -n: must not be negative$"
              ARGS brdf sample --wi 30,0 --material presets/gold.json -n -5)
cli_bad_input(NAME brdf_sample.wi_not_a_pair EXPECT "${E}command line: --wi: expected THETA,PHI in degrees, got \"30:0\"$"
              ARGS brdf sample --material presets/gold.json --wi "30:0")

# --- bench brdf (checks its options, then loads the preset folder before any OpenCL work) --------
cli_bad_input(NAME bench_brdf.samples EXPECT "${E}command line: --samples: must be in \\[1000, 100000000\\]$"
              ARGS bench brdf --samples 5)
cli_bad_input(NAME bench_brdf.threads EXPECT "${E}command line: --threads: must be in \\[1, 256\\]$"
              ARGS bench brdf --threads 0)
cli_bad_input(NAME bench_brdf.model_repeats EXPECT "${E}command line: --model-repeats: must be in \\[0, 100\\]$"
              ARGS bench brdf --model-repeats 101)
cli_bad_input(NAME bench_brdf.preview_seconds EXPECT "${E}command line: --preview-seconds: must be in \\[0, 3600\\]$"
              ARGS bench brdf --preview-seconds nan)
cli_bad_input(NAME bench_brdf.presets_missing EXPECT "${E}/nonexistent-dtoadq: --presets: not a folder of presets"
              ARGS bench brdf --presets /nonexistent-dtoadq)
cli_bad_input(NAME bench_brdf.bad_preset_in_folder EXPECT "${E}${D}/[a-z_]+\\.json: "
              ARGS bench brdf --presets ${D})

# --- bench denoise (checks its options before it renders) -----------------------------------------
cli_bad_input(NAME bench_denoise.reference_spp EXPECT "${E}--reference-spp: 16: must be at least twice the largest --spp and at most 2\\^20$"
              ARGS bench denoise --spp 1,4,16 --reference-spp 16)
cli_bad_input(NAME bench_denoise.spp EXPECT "${E}--spp: 0: must be in \\[1, 65536\\]$"
              ARGS bench denoise --spp 0,4)
cli_bad_input(NAME bench_denoise.passes EXPECT "${E}--passes: 9: must be in \\[1, 8\\]$"
              ARGS bench denoise --passes 9)

cli_bad_input(NAME no_subcommand EXPECT "${E}.*subcommand"
              ARGS)

# --- the plot commands write real files, run away from the source tree ---------------------------
# cli_output_test(NAME MIN_ROWS PNGS CSVS <dtoadq arguments...>)
# cli_output_test(NAME MIN_ROWS PNGS CSVS SETUP <from=to...> ARGS <dtoadq arguments...>)
function(cli_output_test name min_rows pngs csvs)
  set(arguments ${ARGN})
  set(setup "")
  list(GET arguments 0 first)
  if(first STREQUAL "SETUP")
    cmake_parse_arguments(T "" "" "SETUP;ARGS" ${ARGN})
    set(arguments ${T_ARGS})
    string(REPLACE ";" "|" setup "${T_SETUP}")
  endif()
  string(REPLACE ";" "|" args "${arguments}")
  add_test(NAME cli.${name}
           COMMAND ${CMAKE_COMMAND} -DEXE=$<TARGET_FILE:dtoadq> "-DARGS=${args}" -DWORK=${CLI_SCRATCH}/${name} "-DSETUP=${setup}"
                   -DPNGS=${pngs} -DCSVS=${csvs} -DMIN_ROWS=${min_rows} -P ${CLI_TEST_DIR}/expect_output.cmake)
  set_tests_properties(cli.${name} PROPERTIES LABELS cli TIMEOUT 120)
endfunction()
cli_output_test(lobe.writes_png_and_csv 16380 lobe.png lobe.csv
                lobe --material ${PROJECT_SOURCE_DIR}/presets/glossy_plastic.json --material ${PROJECT_SOURCE_DIR}/presets/frosted_glass.json
                --theta-in 40 --phi-in 15 -o lobe.png --csv lobe.csv)
cli_output_test(albedo.writes_png_and_csv 46 albedo.png albedo.csv
                albedo --material ${PROJECT_SOURCE_DIR}/presets/gold.json --strata 16 -o albedo.png --csv albedo.csv)

# --- validate and report ---------------------------------------------------------------------------
# the main job, small: three presets' lobes, albedo, validation and preview (a conductor, a plastic and
# the 2017 model, whose validation fails), the preview sheet, the speed-against-accuracy study on
# short budgets and the stability atlas, with their charts; every preset of presets/ would add a
# preview's kernel build and a validation each and show nothing new; the studio's render (mostly
# dark at 96 x 96, a PNG under 20 kB) is on the page, which the browser test below checks
cli_output_test(report.writes_everything 138
                report/previews.png|report/albedo.png|report/preview_gold.png|report/scene_cornell_box.png|report/speed_preview_glossy_plastic.png|report/speed_scene_caustic.png|report/speed_march_metaballs.png|report/atlas_energy.png|report/atlas_reciprocity.png|report/atlas_march_lost.png|report/atlas_march_steps.png|report/atlas_precision.png|report/atlas_strategies.png
                report/albedo.csv
                SETUP ${PROJECT_SOURCE_DIR}/presets/gold.json=presets/gold.json ${PROJECT_SOURCE_DIR}/presets/glossy_plastic.json=presets/glossy_plastic.json
                      ${PROJECT_SOURCE_DIR}/presets/dtoadq2017_typical.json=presets/dtoadq2017_typical.json
                ARGS report --presets presets --env ${PROJECT_SOURCE_DIR}/envmaps/studio.exr -o report
                --samples 20000 --theta-in 30 --preview-spp 2 --preview-size 96x96
                --scene ${PROJECT_SOURCE_DIR}/scenes/cornell_box.json --studio-scene ${PROJECT_SOURCE_DIR}/scenes/studio.json --scene-spp 2
                --study-seconds 0.2 --study-reference-seconds 0.6 --study-size 48x48
                --study-presets ${PROJECT_SOURCE_DIR}/presets/glossy_plastic.json
                --study-scenes ${PROJECT_SOURCE_DIR}/scenes/caustic.json --study-march-scene ${PROJECT_SOURCE_DIR}/scenes/metaballs.json
                --strategy-scenes ${PROJECT_SOURCE_DIR}/scenes/caustic.json
                --atlas-scene ${PROJECT_SOURCE_DIR}/scenes/metaballs.json)
# its 50 s of CPU pass 120 s on a machine loaded twice over: the timeout is a guard against a hang
set_tests_properties(cli.report.writes_everything PROPERTIES FIXTURES_SETUP report_page TIMEOUT 300)
# its index.html: valid, self-contained, every image and link there, and shown by a browser
add_test(NAME cli.report.page_opens_in_a_browser
         COMMAND ${REPORT_PAGE_PYTHON} ${PROJECT_SOURCE_DIR}/tools/check_report_page.py ${CLI_SCRATCH}/report.writes_everything/report/index.html --browser)
set_tests_properties(cli.report.page_opens_in_a_browser PROPERTIES LABELS cli TIMEOUT 120 FIXTURES_REQUIRED report_page)
cli_bad_input(NAME validate.missing_preset EXPECT "${E}${D}/absent\\.json: cannot open preset file$"
              ARGS validate --material ${D}/absent.json)
cli_bad_input(NAME validate.too_few_samples EXPECT "${E}command line: --samples: "
              ARGS validate --samples 10 --material presets/gold.json)
cli_bad_input(NAME report.quick_and_full EXPECT "--quick excludes --full"
              ARGS report --quick --full -o ${CLI_SCRATCH}/report_budget)
cli_bad_input(NAME report.bad_study_seconds EXPECT "${E}--study-seconds: must be more than 0 and at most 3600$"
              ARGS report --study-seconds nan -o ${CLI_SCRATCH}/report_study_seconds)
cli_bad_input(NAME report.missing_study_scene EXPECT "${E}tests/cli/nope\\.json: no such file \\(--study-scenes; .*"
              ARGS report --study-scenes tests/cli/nope.json -o ${CLI_SCRATCH}/report_study_scene)
cli_bad_input(NAME report.strategy_scene_without_light
              EXPECT "${E}scenes/repetition\\.json: --strategy-scenes: has no light of its own: the strategy atlas renders a scene under its own lights$"
              ARGS report --strategy-scenes scenes/repetition.json -o ${CLI_SCRATCH}/report_strategy_scene)
cli_bad_input(NAME report.missing_atlas_scene EXPECT "${E}tests/cli/nope\\.json: no such file \\(--atlas-scene; .*"
              ARGS report --atlas-scene tests/cli/nope.json -o ${CLI_SCRATCH}/report_atlas_scene)
cli_bad_input(NAME report.no_preset_folder EXPECT "${E}tests/cli/nope: --presets: not a folder of presets .*"
              ARGS report --presets tests/cli/nope -o ${CLI_SCRATCH}/report_none)
cli_bad_input(NAME report.bad_preset_in_folder EXPECT "${E}${D}/[a-z_]+\\.json: [a-z_]+: "
              ARGS report --presets ${D} -o ${CLI_SCRATCH}/report_bad)

# --- preview: every kind of bad input stops before the first sample, and no image is written ----
set(PREVIEW preview --size 16x16 --spp 1 -o ${PNG})
cli_bad_input(NAME preview.malformed_scene ABSENT ${PNG} EXPECT "${E}${D}/scene_malformed\\.json: objects\\[0\\]\\.shape: malformed JSON at line 6, column 3"
              ARGS ${PREVIEW} --scene ${D}/scene_malformed.json)
cli_bad_input(NAME preview.unknown_primitive ABSENT ${PNG} EXPECT "${E}${D}/scene_unknown_primitive\\.json: objects\\[0\\]\\.shape\\.type: unknown node type \"teapot\""
              ARGS ${PREVIEW} --scene ${D}/scene_unknown_primitive.json)
cli_bad_input(NAME preview.missing_scene_preset ABSENT ${PNG} EXPECT "${E}${D}/scene_missing_preset\\.json: materials\\.sample: preset file \"absent_preset\\.json\" not found"
              ARGS ${PREVIEW} --scene ${D}/scene_missing_preset.json)
cli_bad_input(NAME preview.negative_radius ABSENT ${PNG} EXPECT "${E}${D}/scene_negative_radius\\.json: objects\\[0\\]\\.shape\\.radius: value -1 must be > 0$"
              ARGS ${PREVIEW} --scene ${D}/scene_negative_radius.json)
cli_bad_input(NAME preview.missing_scene ABSENT ${PNG} EXPECT "${E}${D}/absent_scene\\.json: "
              ARGS ${PREVIEW} --scene ${D}/absent_scene.json)
cli_bad_input(NAME preview.missing_material ABSENT ${PNG} EXPECT "${E}${D}/absent\\.json: cannot open preset file$"
              ARGS ${PREVIEW} --material ${D}/absent.json)
cli_bad_input(NAME preview.bad_material ABSENT ${PNG} EXPECT "${E}${D}/out_of_range\\.json: ior: value 4 is out of range \\[1, 3\\]$"
              ARGS ${PREVIEW} --material ${D}/out_of_range.json)
cli_bad_input(NAME preview.missing_env ABSENT ${PNG} EXPECT "${E}${D}/absent\\.exr: no such file$"
              ARGS ${PREVIEW} --env ${D}/absent.exr)
cli_bad_input(NAME preview.corrupt_env ABSENT ${PNG} EXPECT "${E}${D}/corrupt\\.exr: cannot be read as an OpenEXR or Radiance HDR image"
              ARGS ${PREVIEW} --env ${D}/corrupt.exr)
cli_bad_input(NAME preview.bad_constant_env ABSENT ${PNG} EXPECT "${E}--env: "
              ARGS ${PREVIEW} --env constant:1,nan,1)
cli_bad_input(NAME preview.zero_size ABSENT ${PNG} EXPECT "${E}--size: 0x16 is outside 1 \\.\\. 16384 pixels a side$"
              ARGS preview --spp 1 -o ${PNG} --size 0x16)
cli_bad_input(NAME preview.absurd_size ABSENT ${PNG} EXPECT "${E}--size: 100000x100000 is outside 1 \\.\\. 16384 pixels a side$"
              ARGS preview --spp 1 -o ${PNG} --size 100000x100000)
cli_bad_input(NAME preview.size_text ABSENT ${PNG} EXPECT "${E}--size: expected WIDTHxHEIGHT, e\\.g\\. 512x512, got \"big\"$"
              ARGS preview --spp 1 -o ${PNG} --size big)
cli_bad_input(NAME preview.zero_spp ABSENT ${PNG} EXPECT "${E}--spp: must be in \\[1, 16777216\\]$"
              ARGS preview --size 16x16 -o ${PNG} --spp 0)
cli_bad_input(NAME preview.nan_exposure ABSENT ${PNG} EXPECT "${E}--env-exposure: value nan is outside"
              ARGS ${PREVIEW} --env-exposure nan)
cli_bad_input(NAME preview.nan_tonemap_exposure ABSENT ${PNG} EXPECT "${E}--exposure: must be a number of stops in \\[-64, 64\\]$"
              ARGS ${PREVIEW} --exposure nan)
cli_bad_input(NAME preview.unknown_sampling ABSENT ${PNG} EXPECT "${E}--ibl-sampling: unknown value \"light\" \\(bsdf, lights, mis, brdf, env\\)$"
              ARGS ${PREVIEW} --ibl-sampling light)
cli_bad_input(NAME preview.unknown_normals ABSENT ${PNG} EXPECT "${E}--normals: unknown value \"sobel\" \\(tetrahedral, central, analytic\\)$"
              ARGS ${PREVIEW} --normals sobel)
cli_bad_input(NAME preview.unknown_reference ABSENT ${PNG} EXPECT "${E}--references: unknown reference \"teapot\" \\(none, all, or a list of chrome, grey, chart, catcher\\)$"
              ARGS ${PREVIEW} --references grey,teapot)
cli_bad_input(NAME preview.ground_word ABSENT ${PNG} EXPECT "${E}--ground: expected on or off, got \"maybe\"$"
              ARGS ${PREVIEW} --ground maybe)
cli_bad_input(NAME preview.unknown_tonemap ABSENT ${PNG} EXPECT "${E}--tonemap: unknown tone map \"filmic\""
              ARGS ${PREVIEW} --tonemap filmic)
cli_bad_input(NAME preview.output_extension EXPECT "${E}${CLI_SCRATCH}/preview\\.jpg: "
              ARGS preview --size 16x16 --spp 1 -o ${CLI_SCRATCH}/preview.jpg)
cli_bad_input(NAME preview.output_folder EXPECT "${E}${CLI_SCRATCH}/absent_folder/preview\\.exr: "
              ARGS preview --size 16x16 --spp 1 -o ${CLI_SCRATCH}/absent_folder/preview.exr)
cli_bad_input(NAME preview.no_device ABSENT ${PNG} STATUS 1 EXPECT "${E}no OpenCL device matches \"no-such-device\""
              ARGS ${PREVIEW} --device no-such-device)
cli_bad_input(NAME bench_preview.bad_seconds EXPECT "${E}--seconds: must be more than 0 and at most 3600$"
              ARGS bench preview --seconds 0)
cli_bad_input(NAME bench_breakdown.bad_local_size EXPECT "${E}--local-sizes: each size must be in \\[1, 4096\\]$"
              ARGS bench breakdown --local-sizes 0)
cli_bad_input(NAME bench_breakdown.bad_repeats EXPECT "${E}--repeats: must be in \\[1, 100\\]$"
              ARGS bench breakdown --repeats 0)

# --- render: bad input ------------------------------------------------------------------------
set(RENDER render scenes/metaballs.json --size 16x16 --spp 1 -o ${PNG})
cli_bad_input(NAME render.missing_scene ABSENT ${PNG} EXPECT "${E}${D}/absent_scene\\.json: cannot open"
              ARGS render ${D}/absent_scene.json --size 16x16 --spp 1 -o ${PNG})
cli_bad_input(NAME render.image_emitter_missing ABSENT ${PNG}
              EXPECT "${E}${D}/scene_image_missing\\.json: emitters\\[0\\]\\.image: ${D}/absent_screen\\.exr: no such file$"
              ARGS render ${D}/scene_image_missing.json --size 16x16 --spp 1 -o ${PNG})
cli_bad_input(NAME render.image_emitter_corrupt ABSENT ${PNG}
              EXPECT "${E}${D}/scene_image_corrupt\\.json: emitters\\[0\\]\\.image: ${D}/corrupt\\.exr: cannot be read as an OpenEXR, Radiance HDR or PNG image$"
              ARGS render ${D}/scene_image_corrupt.json --size 16x16 --spp 1 -o ${PNG})
cli_bad_input(NAME render.unknown_integrator ABSENT ${PNG} EXPECT "${E}--integrator: unknown value \"ppm\" \\(pt, bdpt, lt, bdpt-cache, vcm\\)$"
              ARGS ${RENDER} --integrator ppm)
cli_bad_input(NAME render.bdpt_max_depth ABSENT ${PNG} EXPECT "${E}--max-depth: bdpt takes at most 62 scattering events, got 63$"
              ARGS ${RENDER} --integrator bdpt --max-depth 63)
cli_bad_input(NAME render.bdpt_no_light ABSENT ${PNG}
              EXPECT "${E}${D}/scene_no_sample\\.json: --integrator: bdpt starts its light subpaths on the lights, and the scene has none .*give --env$"
              ARGS render ${D}/scene_no_sample.json --integrator bdpt --size 16x16 --spp 1 -o ${PNG})
cli_bad_input(NAME render.lt_no_light ABSENT ${PNG}
              EXPECT "${E}${D}/scene_no_sample\\.json: --integrator: lt starts its light subpaths on the lights, and the scene has none "
              ARGS render ${D}/scene_no_sample.json --integrator lt --size 16x16 --spp 1 -o ${PNG})
cli_bad_input(NAME render.lt_emissive_material ABSENT ${PNG}
              EXPECT "${E}${D}/scene_emissive\\.json: materials\\.lamp: emission_luminance: the light tracer cannot see a material's emission .*: use --integrator bdpt or pt$"
              ARGS render ${D}/scene_emissive.json --integrator lt --size 16x16 --spp 1 -o ${PNG})
cli_bad_input(NAME render.lt_environment ABSENT ${PNG}
              EXPECT "${E}scenes/metaballs\\.json: --integrator: lt cannot render an environment light .*: use --integrator bdpt or pt$"
              ARGS ${RENDER} --integrator lt --env constant:1,1,1)
cli_bad_input(NAME render.cache_light_paths ABSENT ${PNG}
              EXPECT "${E}--light-paths: light subpaths per pixel must be in .0, 16., got 0$"
              ARGS ${RENDER} --integrator bdpt-cache --light-paths 0)
cli_bad_input(NAME render.cache_connections ABSENT ${PNG} EXPECT "${E}--connections: must be in \\[1, 64\\], got 65$"
              ARGS ${RENDER} --integrator bdpt-cache --connections 65)
cli_bad_input(NAME render.cache_too_large ABSENT ${PNG} EXPECT "${E}--light-paths: the light-vertex cache would take 2176 MiB .*"
              ARGS render scenes/metaballs.json --size 1024x1024 --spp 1 -o ${PNG} --integrator bdpt-cache --light-paths 1)
cli_bad_input(NAME render.merge_radius_zero ABSENT ${PNG} EXPECT "${E}--merge-radius: must be a positive length, got 0$"
              ARGS ${RENDER} --integrator vcm --merge-radius 0)
cli_bad_input(NAME render.merge_radius_nan ABSENT ${PNG} EXPECT "${E}--merge-radius: must be a positive length, got nan$"
              ARGS ${RENDER} --integrator vcm --merge-radius nan)
cli_bad_input(NAME render.connection_roulette ABSENT ${PNG} EXPECT "${E}--connection-roulette: must be a weight in .0, 1.$"
              ARGS ${RENDER} --integrator bdpt --connection-roulette 1)
cli_bad_input(NAME render.unknown_mis ABSENT ${PNG} EXPECT "${E}--mis: unknown value \"max\" \\(balance, power\\)$"
              ARGS ${RENDER} --integrator bdpt --mis max)
cli_bad_input(NAME render.strategies_with_pt ABSENT ${PNG} EXPECT "${E}--strategies: needs --integrator bdpt, lt, bdpt-cache or vcm"
              ARGS ${RENDER} --strategies ${CLI_SCRATCH}/strategies_pt)
# the --strategies folder is checked before the render (nothing is written), and a folder the check
# made is removed when another input error stops the command
set(RENDER_BDPT render scenes/cornell_box.json --integrator bdpt --size 8x8 --spp 1 -o ${PNG})
cli_bad_input(NAME render.strategies_folder_is_a_file ABSENT ${PNG} EXPECT "${E}README\\.md: --strategies: is a file, not a folder$"
              ARGS ${RENDER_BDPT} --strategies README.md)
cli_bad_input(NAME render.strategies_folder_under_a_file ABSENT ${PNG}
              EXPECT "${E}README\\.md/strategies: --strategies: cannot create the folder \\(.+\\)$"
              ARGS ${RENDER_BDPT} --strategies README.md/strategies)
cli_bad_input(NAME render.strategies_folder_left_out ABSENT ${CLI_SCRATCH}/strategies_unmade EXPECT "${E}--spp: must be in"
              ARGS render scenes/cornell_box.json --integrator bdpt --size 8x8 --spp 0 -o ${PNG} --strategies ${CLI_SCRATCH}/strategies_unmade/sub)
cli_bad_input(NAME render.unknown_light_sampling ABSENT ${PNG} EXPECT "${E}--light-sampling: unknown value \"all\" "
              ARGS ${RENDER} --light-sampling all)
cli_bad_input(NAME render.unknown_light_selection ABSENT ${PNG} EXPECT "${E}--light-selection: unknown value \"random\" "
              ARGS ${RENDER} --light-selection random)
# --aov: an unknown AOV, and AOVs asked of a PNG (no layers), stop the command before the render
cli_bad_input(NAME render.unknown_aov ABSENT ${PNG} EXPECT "${E}--aov: unknown AOV \"albdo\" \\(expected a comma-separated list of albedo, normal, depth, slot, variance, samples\\)$"
              ARGS ${RENDER} --aov albedo,albdo)
cli_bad_input(NAME preview.aov_to_png ABSENT ${PNG} EXPECT "${E}--aov: AOVs are EXR layers, and .*\\.png is not an \\.exr"
              ARGS preview --size 8x8 --spp 1 --aov depth -o ${PNG})
cli_bad_input(NAME render.no_sample_slot ABSENT ${PNG} EXPECT "${E}${D}/scene_no_sample\\.json: materials: no material named \"sample\""
              ARGS render ${D}/scene_no_sample.json --material presets/gold.json --size 16x16 --spp 1 -o ${PNG})

# --- preview and render write a linear EXR with its metadata and an sRGB PNG beside it ------------
add_test(NAME cli.render.writes_exr_and_png
         COMMAND ${CMAKE_COMMAND} -DEXE=$<TARGET_FILE:dtoadq> -DWORK=${CLI_SCRATCH}/render_output -DSOURCE=${PROJECT_SOURCE_DIR}
                 -P ${CLI_TEST_DIR}/expect_render_output.cmake)
set_tests_properties(cli.render.writes_exr_and_png PROPERTIES LABELS cli TIMEOUT 120)
add_test(NAME cli.preview.denoise_keeps_the_raw_image
         COMMAND ${CMAKE_COMMAND} -DEXE=$<TARGET_FILE:dtoadq> -DWORK=${CLI_SCRATCH}/denoise_layers -P ${CLI_TEST_DIR}/expect_denoise_layers.cmake)
set_tests_properties(cli.preview.denoise_keeps_the_raw_image PROPERTIES LABELS cli TIMEOUT 60)
cli_bad_input(NAME preview.denoise_word ABSENT ${PNG} EXPECT "${E}--denoise: expected on or off, got \"yes\"$"
              ARGS preview --size 8x8 --spp 1 --denoise yes -o ${PNG})
# the backdrop's controls: out of range, and the shadow catcher under BDPT, stop before the render
cli_bad_input(NAME render.background_opacity_range ABSENT ${PNG} EXPECT "${E}--background-opacity: must be a number in \\[0, 1\\]$"
              ARGS ${RENDER} --background-opacity 1.5)
cli_bad_input(NAME render.background_blur_range ABSENT ${PNG} EXPECT "${E}--background-blur: must be a number of degrees in \\[0, 90\\]$"
              ARGS ${RENDER} --background-blur -1)
cli_bad_input(NAME preview.shadow_catcher_bdpt ABSENT ${PNG}
              EXPECT "${E}.*: --integrator: the shadow catcher \\(material \"shadow_catcher\"\\) is rendered by the path tracer only: use --integrator pt$"
              ARGS render scenes/shader_ball.json --env constant:1,1,1 --size 8x8 --spp 1 --integrator bdpt --shadow-catcher -o ${PNG})
add_test(NAME cli.preview.background_alpha
         COMMAND ${CMAKE_COMMAND} -DEXE=$<TARGET_FILE:dtoadq> -DWORK=${CLI_SCRATCH}/background_alpha -P ${CLI_TEST_DIR}/expect_background_alpha.cmake)
set_tests_properties(cli.preview.background_alpha PROPERTIES LABELS cli TIMEOUT 60)
add_test(NAME cli.render.writes_aov_layers
         COMMAND ${CMAKE_COMMAND} -DEXE=$<TARGET_FILE:dtoadq> -DWORK=${CLI_SCRATCH}/aov_layers -DSOURCE=${PROJECT_SOURCE_DIR}
                 -P ${CLI_TEST_DIR}/expect_aov_layers.cmake)
set_tests_properties(cli.render.writes_aov_layers PROPERTIES LABELS cli TIMEOUT 60)

cli_bad_input(NAME bench.compare_to_missing EXPECT "${E}${D}/absent_binary: is not an executable file$"
              ARGS bench compare --to ${D}/absent_binary)
cli_bad_input(NAME bench.compare_object_counts EXPECT "${E}--object-counts: each count must be in \\[1, 4096\\]$"
              ARGS bench compare --to /bin/true --object-counts 0)

# --- BDPT's strategies, one image each (render --strategies DIR) ------------------------------------
add_test(NAME cli.render.strategy_images
         COMMAND ${CMAKE_COMMAND} -DEXE=$<TARGET_FILE:dtoadq> -DWORK=${CLI_SCRATCH}/strategy_images -DSOURCE=${PROJECT_SOURCE_DIR}
                 -P ${CLI_TEST_DIR}/expect_strategy_images.cmake)
set_tests_properties(cli.render.strategy_images PROPERTIES LABELS cli TIMEOUT 120)
add_test(NAME cli.render.strategy_images_cache
         COMMAND ${CMAKE_COMMAND} -DEXE=$<TARGET_FILE:dtoadq> -DWORK=${CLI_SCRATCH}/strategy_images_cache -DSOURCE=${PROJECT_SOURCE_DIR}
                 -DINTEGRATOR=bdpt-cache -P ${CLI_TEST_DIR}/expect_strategy_images.cmake)
set_tests_properties(cli.render.strategy_images_cache PROPERTIES LABELS cli TIMEOUT 120)

# --- a render split by sample range (render --samples A:B), merged (dtoadq merge) and resumed ----
add_test(NAME cli.render.split_merge_resume
         COMMAND ${CMAKE_COMMAND} -DEXE=$<TARGET_FILE:dtoadq> -DWORK=${CLI_SCRATCH}/split_render -DSOURCE=${PROJECT_SOURCE_DIR}
                 -P ${CLI_TEST_DIR}/expect_split_render.cmake)
set_tests_properties(cli.render.split_merge_resume PROPERTIES LABELS cli TIMEOUT 120)

# --- no OpenCL platform at all: the ICD loader is pointed at an empty vendor folder ---------------
file(MAKE_DIRECTORY ${CLI_SCRATCH}/no_icd_vendors)
set(NO_PLATFORM_ARGS_devices "devices")
set(NO_PLATFORM_ARGS_preview "preview|--size|8x8|--spp|1|-o|${CLI_SCRATCH}/no_platform.exr")
foreach(command devices preview)
  add_test(NAME cli.${command}.no_opencl_platform
           COMMAND ${CMAKE_COMMAND} -E env OCL_ICD_VENDORS=${CLI_SCRATCH}/no_icd_vendors
                   ${CMAKE_COMMAND} -DEXE=$<TARGET_FILE:dtoadq> "-DARGS=${NO_PLATFORM_ARGS_${command}}" -DABSENT=${CLI_SCRATCH}/no_platform.exr -DSTATUS=1
                   "-DEXPECT=${E}no OpenCL device found: no platform reports a device \\(is an OpenCL driver such as pocl-opencl-icd installed\\?\\)$"
                   -P ${CLI_TEST_DIR}/expect_error.cmake
           WORKING_DIRECTORY ${PROJECT_SOURCE_DIR})
  set_tests_properties(cli.${command}.no_opencl_platform PROPERTIES LABELS cli TIMEOUT 60)
endforeach()

# --- Ctrl-C, a vanished output folder: what was rendered is kept --------------------------------
# run_and_interrupt sends SIGINT (or removes a folder) once the command's output shows a text;
# expect_interrupted.cmake checks the exit status, the output and that every EXR is complete and
# says how many samples per pixel it holds.
add_executable(run_and_interrupt ${CLI_TEST_DIR}/run_and_interrupt.cpp)
# cli_interrupt_test(NAME <name> TRIGGER <text> DELAY <seconds> [ACTION <action>] [STATUS <exit>]
#                    [EXRS <files>] [MIN_SPP n] [MAX_SPP n] [MAY_BE_ABSENT] [ABSENT <files>] [MKDIRS <folders>]
#                    [SETUP <from=to...>] [ENV <VAR=value...>] EXPECT <regexes...> ARGS <dtoadq arguments...>)
function(cli_interrupt_test)
  cmake_parse_arguments(T "MAY_BE_ABSENT" "NAME;TRIGGER;DELAY;ACTION;STATUS;MIN_SPP;MAX_SPP" "EXRS;ABSENT;MKDIRS;SETUP;ENV;EXPECT;ARGS" ${ARGN})
  set(work ${CLI_SCRATCH}/${T_NAME})
  set(defines -DHELPER=$<TARGET_FILE:run_and_interrupt> -DEXE=$<TARGET_FILE:dtoadq> -DWORK=${work} "-DTRIGGER=${T_TRIGGER}" -DDELAY=${T_DELAY})
  foreach(list_name ARGS EXPECT EXRS ABSENT MKDIRS SETUP)
    string(REPLACE ";" "|" joined "${T_${list_name}}")
    string(REPLACE "@WORK@" "${work}" joined "${joined}")
    list(APPEND defines "-D${list_name}=${joined}")
  endforeach()
  foreach(scalar ACTION STATUS MIN_SPP MAX_SPP)
    if(DEFINED T_${scalar})
      string(REPLACE "@WORK@" "${work}" value "${T_${scalar}}")
      list(APPEND defines "-D${scalar}=${value}")
    endif()
  endforeach()
  if(T_MAY_BE_ABSENT)
    list(APPEND defines -DMAY_BE_ABSENT=1)
  endif()
  string(REPLACE "@WORK@" "${work}" env "${T_ENV}")
  add_test(NAME cli.${T_NAME} COMMAND ${CMAKE_COMMAND} -E env ${env} ${CMAKE_COMMAND} ${defines} -P ${CLI_TEST_DIR}/expect_interrupted.cmake)
  set_tests_properties(cli.${T_NAME} PROPERTIES LABELS cli TIMEOUT 500)
endfunction()

set(SRC ${PROJECT_SOURCE_DIR})
# Ctrl-C during a preview that would take hours: the image so far is written, its header says how
# many samples it holds, and the exit status is 130.
cli_interrupt_test(NAME preview.ctrl_c TRIGGER "kernel built in" DELAY 2
                   EXRS out.exr MIN_SPP 1 MAX_SPP 16777215
                   EXPECT "interrupted after [1-9][0-9]* samples per pixel; the image so far was written"
                   ARGS preview --material ${SRC}/presets/gold.json --env constant:1,1,1 --size 64x64 --spp 16777216 -o out.exr)
# The same for `render`, on the OpenCL device and on the host build.
foreach(device cpu host)
  cli_interrupt_test(NAME render.ctrl_c_${device} TRIGGER "kernel built in" DELAY 2
                     EXRS out.exr MIN_SPP 1 MAX_SPP 16777215
                     EXPECT "interrupted after [1-9][0-9]* samples per pixel; the image so far was written"
                     ARGS render ${SRC}/scenes/cornell_box.json --device ${device} --size 48x48 --spp 16777216 -o out.exr)
endforeach()
# Ctrl-C in a sequence's first frame: that frame is written with its samples so far (the next run
# continues it, tests/cli/sequence_test.py) and the sequence stops there.
cli_interrupt_test(NAME render.sequence_ctrl_c TRIGGER "kernel built in" DELAY 0.3
                   EXRS f_0001.exr MIN_SPP 1 MAX_SPP 16777215 ABSENT f_0002.exr
                   EXPECT "interrupted after [1-9][0-9]* samples per pixel; the image so far was written"
                   ARGS render ${SRC}/tests/scene_data/animated.json --device host --size 24x16 --spp 16777216 --frames 1:3 --fps 4 -o f_%04d.exr)
# A second Ctrl-C right after the first stops at once, during the write if it comes then: the EXR is
# absent or complete, never truncated (writes are atomic).
cli_interrupt_test(NAME preview.second_ctrl_c TRIGGER "kernel built in" DELAY 2 ACTION int,0.02
                   EXRS out.exr MIN_SPP 1 MAX_SPP 16777215 MAY_BE_ABSENT
                   EXPECT "interrupted"
                   ARGS preview --material ${SRC}/presets/gold.json --env constant:1,1,1 --size 256x256 --spp 16777216 -o out.exr)
# The output folder vanishes while the preview renders: the render goes to the temporary folder
# and the one-line error (exit 2) says where.
cli_interrupt_test(NAME preview.output_folder_vanishes TRIGGER "kernel built in" DELAY 0 ACTION remove=@WORK@/out STATUS 2
                   MKDIRS out tmp ENV TMPDIR=@WORK@/tmp
                   EXRS tmp/dtoadq-render-*.exr MIN_SPP 64 MAX_SPP 64
                   EXPECT "dtoadq: error: out/preview\\.exr: cannot write .*; the render was saved to .*/tmp/dtoadq-render-[0-9]+\\.exr"
                   ARGS preview --material ${SRC}/presets/gold.json --env constant:1,1,1 --size 64x64 --spp 64 -o out/preview.exr)
# Ctrl-C during a report's second preview (its kernel build): the report stops, says what it
# finished, and the first preview is complete.
set(REPORT_PRESETS SETUP ${SRC}/presets/copper.json=presets/copper.json ${SRC}/presets/gold.json=presets/gold.json)
cli_interrupt_test(NAME report.ctrl_c_between_presets TRIGGER "report: preview of gold" DELAY 0 ${REPORT_PRESETS}
                   EXRS report/preview_copper.exr MIN_SPP 16 MAX_SPP 16 ABSENT report/preview_gold.exr report/index.html
                   EXPECT "dtoadq: report interrupted; finished: the lobe plots, the albedo chart, the preview of copper \\(2 presets in all\\)"
                   ARGS report --presets presets --env ${SRC}/envmaps/studio.exr --scene ${SRC}/scenes/cornell_box.json --studio-scene ${SRC}/scenes/studio.json -o report --samples 20000 --theta-in 30 --no-study --no-strategies
                        --atlas-scene ${SRC}/scenes/metaballs.json
                        --preview-spp 16 --preview-size 32x32)
# Ctrl-C during a preview of a report: that preview is written with the samples it holds.
cli_interrupt_test(NAME report.ctrl_c_during_preview TRIGGER "report: preview of copper" DELAY 4 ${REPORT_PRESETS}
                   EXRS report/preview_copper.exr MIN_SPP 1 MAX_SPP 999999 ABSENT report/preview_gold.exr report/index.html
                   EXPECT "dtoadq: report interrupted; finished: the lobe plots, the albedo chart; cut short: the preview of copper \\([0-9]+ of 1000000 samples per pixel, written\\)"
                   ARGS report --presets presets --env ${SRC}/envmaps/studio.exr --scene ${SRC}/scenes/cornell_box.json --studio-scene ${SRC}/scenes/studio.json -o report --samples 20000 --theta-in 30 --no-study --no-strategies
                        --atlas-scene ${SRC}/scenes/metaballs.json
                        --preview-spp 1000000 --preview-size 32x32)

# --- validate: a physical failure is a non-zero exit (1), a pass is 0 -----------------------------
function(cli_status_test name status expect)
  string(REPLACE ";" "|" args "${ARGN}")
  add_test(NAME cli.${name} COMMAND ${CMAKE_COMMAND} -DEXE=$<TARGET_FILE:dtoadq> "-DARGS=${args}" -DSTATUS=${status} "-DEXPECT=${expect}"
                                    -P ${CLI_TEST_DIR}/expect_status.cmake WORKING_DIRECTORY ${PROJECT_SOURCE_DIR})
  set_tests_properties(cli.${name} PROPERTIES LABELS cli TIMEOUT 300)
endfunction()
cli_status_test(validate.physical_failure_exits_1 1 "FAIL" validate --samples 20000 --material presets/dtoadq2017_typical.json)
cli_status_test(validate.pass_exits_0 0 "PASS" validate --samples 20000 --material presets/gold.json)

# --- non-finite samples are reported on stderr and in the EXR's metadata ---------------------------
cli_status_test(preview.reports_nonfinite_samples 0 "dtoadq: warning: [1-9][0-9]* non-finite samples \\(NaN or infinite\\) were left out of the image"
                preview --env constant:3e38,3e38,3e38 --ibl-sampling env --ground off --size 16x16 --spp 1 --quiet
                -o ${CLI_SCRATCH}/nonfinite.exr)

# --- dtoadq view (docs/viewer.md) --------------------------------------------------------------------
# Bad input stops before the window opens: these need no display.
cli_bad_input(NAME view.bad_preset EXPECT "${E}${D}/out_of_range\\.json: ior: value 4 is out of range \\[1, 3\\]$"
              ARGS view --material ${D}/out_of_range.json)
cli_bad_input(NAME view.missing_env EXPECT "${E}${D}/absent\\.exr: no such file$" ARGS view --env ${D}/absent.exr)
cli_bad_input(NAME view.bad_constant_env EXPECT "${E}--env: constant: G is not a number" ARGS view --env constant:1,x,1)
cli_bad_input(NAME view.set_unknown_key EXPECT "${E}--set: roughnes: unknown key$" ARGS view --frames 2 --set roughnes=0.2@1)
cli_bad_input(NAME view.set_out_of_range EXPECT "${E}--set: roughness: value 2 is out of range \\[0, 1\\]$" ARGS view --frames 2 --set roughness=2@1)
cli_bad_input(NAME view.bad_export_target EXPECT "${E}--export-to: expected SCENE\\.json:NAME" ARGS view --export-to nope)
# a material file of another tool is exported on exit; an unknown extension is neither
cli_bad_input(NAME view.bad_export_extension EXPECT "${E}--export-to: expected SCENE\\.json:NAME or a material file FILE\\.mtlx.\\.gltf.\\.xml.\\.pbrt, got \"out\\.txt\"$"
              ARGS view --export-to out.txt)
cli_bad_input(NAME view.move_unknown_key EXPECT "${E}--move: spin: unknown key \\(orbit, env_rotation, env_exposure, background_blur, background_opacity\\)$" ARGS view --frames 2 --move spin=3@1)
cli_bad_input(NAME view.unknown_reference_load EXPECT "${E}--load-references: unknown reference \"ball\" \\(none, all, or a list of chrome, grey, chart, catcher\\)$"
              ARGS view --frames 2 --load-references ball@1)
cli_bad_input(NAME view.window_too_small EXPECT "${E}--window: 300x200 is smaller than the panel and a render beside it \\(504x240 at least\\)$"
              ARGS view --window 300x200)
cli_bad_input(NAME view.resize_not_a_size EXPECT "${E}--resize: expected WIDTHxHEIGHT, e\\.g\\. 512x512, got \"wide\"$" ARGS view --frames 2 --resize wide@1)
cli_bad_input(NAME view.resize_needs_frames EXPECT "${E}--resize: needs --frames \\(a scripted run\\)$" ARGS view --resize 800x600@1)
cli_bad_input(NAME view.unknown_display EXPECT "${E}--display: unknown value \"stretch\" \\(render, scale\\)$" ARGS view --display stretch)
cli_bad_input(NAME view.unknown_section EXPECT "${E}--open: unknown section \"Lobes\" \\(Material, Checks, Lobe, Environment, Presets, Inspector, Help, all\\)$"
              ARGS view --open Lobes)
cli_bad_input(NAME view.max_render_pixels_too_few EXPECT "${E}--max-render-pixels: must be in \\[64, 268435456\\]$" ARGS view --max-render-pixels 10)
cli_bad_input(NAME view.unknown_view_mode EXPECT "${E}--view-mode: unknown view \"albedoo\" \\(expected one of image, albedo, normal, depth, slot, samples, variance, false-colour, relative-error, gamut\\)$"
              ARGS view --frames 2 --view-mode albedoo@1)
cli_bad_input(NAME view.error_threshold_not_positive EXPECT "${E}--error-threshold: must be a relative standard error above 0, at most 1e6$"
              ARGS view --frames 2 --error-threshold 0)
cli_bad_input(NAME view.save_layers_without_exr EXPECT "${E}--save-layers: needs --save-exr$" ARGS view --frames 2 --save-layers depth)
cli_bad_input(NAME view.save_layers_unknown EXPECT "${E}--save-layers: unknown AOV \"dpth\" " ARGS view --frames 2 --save-exr v.exr --save-layers dpth)
cli_bad_input(NAME view.move_bad_orbit EXPECT "${E}--move: orbit: expected DX,DY in pixels, got \"3\"$" ARGS view --frames 2 --move orbit=3@1)
# The window itself, under Xvfb with Mesa's software OpenGL when there is no DISPLAY (skipped, exit
# 77, when neither is there). The Debian python3: the PNGs are read with its matplotlib.
find_program(VIEW_TEST_PYTHON python3 PATHS /usr/bin NO_DEFAULT_PATH)
if(NOT VIEW_TEST_PYTHON)
  find_program(VIEW_TEST_PYTHON python3)
endif()
foreach(view_case accumulate set preset export env references background resize sections denoise denoise_wait views)
  add_test(NAME cli.view.${view_case}
           COMMAND ${VIEW_TEST_PYTHON} ${CLI_TEST_DIR}/view_test.py $<TARGET_FILE:dtoadq> ${CLI_SCRATCH}/view_${view_case} ${view_case})
  # One at a time: xvfb-run -a started twice at once can pick the same display number.
  set_tests_properties(cli.view.${view_case} PROPERTIES LABELS cli TIMEOUT 240 SKIP_RETURN_CODE 77 RESOURCE_LOCK xvfb)
endforeach()

# The turntable (headless, on the host renderer): the model turns under still lighting, the map
# turns around the model, a video has every frame (skipped, exit 77, without ffmpeg).
foreach(turntable_case model environment video)
  add_test(NAME cli.view.turntable_${turntable_case}
           COMMAND ${VIEW_TEST_PYTHON} ${CLI_TEST_DIR}/turntable_test.py $<TARGET_FILE:dtoadq> ${PROJECT_SOURCE_DIR}/envmaps/studio.exr
                   ${CLI_SCRATCH}/turntable_${turntable_case} ${turntable_case})
  set_tests_properties(cli.view.turntable_${turntable_case} PROPERTIES LABELS cli TIMEOUT 300 SKIP_RETURN_CODE 77)
endforeach()
cli_bad_input(NAME view.turntable_frames EXPECT "${E}--turntable: must be a number of frames in \\[1, 100000\\]$" ARGS view --turntable -2 -o x.mp4)
cli_bad_input(NAME view.turntable_no_output EXPECT "${E}--output: --turntable needs -o: " ARGS view --turntable 4)
cli_bad_input(NAME view.turntable_turn EXPECT "${E}--turn: expected model or environment, got \"spin\"$"
              ARGS view --turntable 4 --turn spin -o ${CLI_SCRATCH}/f_%02d.png)
cli_bad_input(NAME view.turntable_output EXPECT "${E}${CLI_SCRATCH}/turn\\.gif: expected a video \\(\\.mp4\\) or a frame pattern with one %d"
              ARGS view --turntable 4 -o ${CLI_SCRATCH}/turn.gif)

# --- sequences (render --frames A:B --fps N, cli/render_sequence.hpp) on the host renderer: frame k is
# the single render at k / N bit for bit, a sequence resumes, --video has every frame (skipped, exit
# 77, without ffmpeg once the missing-ffmpeg error is checked) ------------------------------------
foreach(sequence_case identity resume video)
  add_test(NAME cli.render.sequence_${sequence_case}
           COMMAND ${VIEW_TEST_PYTHON} ${CLI_TEST_DIR}/sequence_test.py $<TARGET_FILE:dtoadq> ${PROJECT_SOURCE_DIR}/tests/scene_data/animated.json
                   ${CLI_SCRATCH}/sequence_${sequence_case} ${sequence_case})
  set_tests_properties(cli.render.sequence_${sequence_case} PROPERTIES LABELS cli TIMEOUT 120 SKIP_RETURN_CODE 77)
endforeach()
# the TV room's screen plays its PNG sequence: frame 2 at 4 frames/s (t = 0.5) shows the screen's frame 6
add_test(NAME cli.render.sequence_screen
         COMMAND ${VIEW_TEST_PYTHON} ${CLI_TEST_DIR}/sequence_test.py $<TARGET_FILE:dtoadq> ${PROJECT_SOURCE_DIR}/scenes/tv_room.json
                 ${CLI_SCRATCH}/sequence_screen identity)
set_tests_properties(cli.render.sequence_screen PROPERTIES LABELS cli TIMEOUT 120)
set(SEQUENCE render tests/scene_data/animated.json --device host --size 8x8 --quiet)
# every frame of the screen's sequence is checked before the first is rendered: it has 12 (0 to 11)
cli_bad_input(NAME render.frames_screen_missing ABSENT ${CLI_SCRATCH}/tv_0010.exr
              EXPECT "${E}scenes/tv_room\\.json: emitters\\[0\\]\\.image: scenes/tv_room/screen_0012\\.png: no such file: frame 12 of the sequence scenes/tv_room/screen_%04d\\.png at t = 1 s$"
              ARGS render scenes/tv_room.json --device host --size 8x8 --quiet --frames 10:14 --fps 12 -o ${CLI_SCRATCH}/tv_%04d.exr)
cli_bad_input(NAME render.frames_backwards EXPECT "${E}--frames: expected A:B, frame numbers with 0 <= A < B \\(frames A to B-1\\), got \"3:1\"$"
              ARGS ${SEQUENCE} --frames 3:1 --fps 24 -o ${CLI_SCRATCH}/s_%04d.exr)
cli_bad_input(NAME render.frames_no_fps EXPECT "${E}--fps: --frames needs the frames per second of scene time, in .0, 1000.$"
              ARGS ${SEQUENCE} --frames 0:2 -o ${CLI_SCRATCH}/s_%04d.exr)
cli_bad_input(NAME render.fps_without_frames EXPECT "${E}--fps: needs --frames A:B$" ARGS ${SEQUENCE} --fps 24 -o ${PNG})
cli_bad_input(NAME render.frames_no_conversion ABSENT ${CLI_SCRATCH}/s.exr
              EXPECT "${E}${CLI_SCRATCH}/s\\.exr: the output of --frames needs one %d or %0Nd for the frame number \\(frame_%04d\\.exr\\), and this has no %d$"
              ARGS ${SEQUENCE} --frames 0:2 --fps 24 -o ${CLI_SCRATCH}/s.exr)
cli_bad_input(NAME render.frames_two_conversions
              EXPECT "${E}${CLI_SCRATCH}/s_%d_%04d\\.exr: the output of --frames needs one %d or %0Nd for the frame number \\(frame_%04d\\.exr\\), and this has 2 of them$"
              ARGS ${SEQUENCE} --frames 0:2 --fps 24 -o ${CLI_SCRATCH}/s_%d_%04d.exr)
cli_bad_input(NAME render.frames_with_time EXPECT "${E}--time: a sequence renders --spp samples per frame"
              ARGS ${SEQUENCE} --frames 0:2 --fps 24 --time 5 -o ${CLI_SCRATCH}/s_%04d.exr)
cli_bad_input(NAME render.frames_video_extension EXPECT "${E}${CLI_SCRATCH}/s\\.gif: --video writes an H\\.264 video: expected an \\.mp4$"
              ARGS ${SEQUENCE} --frames 0:2 --fps 24 --video ${CLI_SCRATCH}/s.gif -o ${CLI_SCRATCH}/s_%04d.exr)
cli_bad_input(NAME render.scene_time_not_a_number ABSENT ${PNG} EXPECT "${E}.*--scene-time.*soon"
              ARGS ${SEQUENCE} --scene-time soon -o ${PNG})
# every frame's camera is checked before the first is rendered: fov 179, 179, 1 (Catmull-Rom) overshoots at t = 0.5
cli_bad_input(NAME render.frames_camera_overshoots ABSENT ${CLI_SCRATCH}/o_0000.exr
              EXPECT "${E}${D}/scene_keyframes_overshoot\\.json: camera\\.keyframes: at t = 0\\.5 s the camera's fov_degrees value 190\\.125 is out of range \\(0, 180\\)$"
              ARGS render ${D}/scene_keyframes_overshoot.json --device host --size 8x8 --quiet --frames 0:3 --fps 2 -o ${CLI_SCRATCH}/o_%04d.exr)
cli_bad_input(NAME render.bad_keyframes ABSENT ${PNG}
              EXPECT "${E}${D}/scene_bad_keyframes\\.json: camera\\.keyframes\\.times\\[2\\]: time 1 is not after the one before it \\(2\\): times must increase strictly$"
              ARGS render ${D}/scene_bad_keyframes.json --device host --size 8x8 --quiet -o ${PNG})

# --- fit (docs/fitting.md): a bad measured file and bad options, each one line, no preset written --
set(FIT fit -o ${PNG}.json --quiet --measured)
cli_bad_input(NAME fit.missing_file ABSENT ${PNG}.json EXPECT "${E}${D}/absent\\.binary: cannot open the measured BRDF file$"
              ARGS ${FIT} ${D}/absent.binary)
cli_bad_input(NAME fit.truncated_file ABSENT ${PNG}.json EXPECT "${E}${D}/truncated\\.binary: data: truncated: 44 bytes, expected 34992012$"
              ARGS ${FIT} ${D}/truncated.binary)
cli_bad_input(NAME fit.distribution ABSENT ${PNG}.json EXPECT "${E}command line: --distribution: expected ggx or hyper_cauchy, got \"beckmann\"$"
              ARGS ${FIT} ${D}/truncated.binary --distribution beckmann)
cli_bad_input(NAME fit.lobes ABSENT ${PNG}.json EXPECT "${E}command line: --lobes: \"transmission\" cannot be fitted"
              ARGS ${FIT} ${D}/truncated.binary --lobes diffuse,transmission)
cli_bad_input(NAME fit.stride ABSENT ${PNG}.json EXPECT "${E}command line: --stride: expected THETA_H,THETA_D,PHI_D bin strides, got \"3,3\"$"
              ARGS ${FIT} ${D}/truncated.binary --stride 3,3)

# --- convert: materials between presets, MaterialX and glTF (docs/interchange.md) ---------------
cli_bad_input(NAME convert.mtlx_unknown_node ABSENT ${PNG}
              EXPECT "${E}${D}/unknown_node\\.mtlx: SR_a: unknown node <gltf_pbr> \\(the lab converts open_pbr_surface and standard_surface\\)$"
              ARGS convert ${D}/unknown_node.mtlx --to mtlx -o ${PNG})
cli_bad_input(NAME convert.mtlx_missing_material ABSENT ${PNG}
              EXPECT "${E}${D}/no_material\\.mtlx: materialx: missing material: the document holds no <surfacematerial>$"
              ARGS convert ${D}/no_material.mtlx --to gltf -o ${PNG})
cli_bad_input(NAME convert.mtlx_wrong_type ABSENT ${PNG}
              EXPECT "${E}${D}/wrong_type\\.mtlx: SR_a/base_color: wrong type \"float\" \\(open_pbr_surface's base_color is color3\\)$"
              ARGS convert ${D}/wrong_type.mtlx --to preset -o ${PNG})
cli_bad_input(NAME convert.mtlx_malformed ABSENT ${PNG} EXPECT "${E}${D}/malformed\\.mtlx: malformed XML: .* at byte [0-9]+$"
              ARGS convert ${D}/malformed.mtlx --to preset -o ${PNG})
cli_bad_input(NAME convert.gltf_out_of_range ABSENT ${PNG}
              EXPECT "${E}${D}/ior_out_of_range\\.gltf: materials.0.\\.extensions\\.KHR_materials_ior\\.ior: value 3\\.5 is out of range .1, 3.$"
              ARGS convert ${D}/ior_out_of_range.gltf --to mtlx -o ${PNG})
cli_bad_input(NAME convert.gltf_missing_material ABSENT ${PNG}
              EXPECT "${E}${D}/no_material\\.gltf: materials: missing material: the document holds no materials$"
              ARGS convert ${D}/no_material.gltf --to mtlx -o ${PNG})
# the fit's options are checked before the input is read (the input here does not exist)
cli_bad_input(NAME convert.fit_evaluations_out_of_range ABSENT ${PNG}
              EXPECT "${E}command line: --fit-evaluations: must be in \\[10, 1000000\\], got 5$"
              ARGS convert ${D}/no_such_material.json --fit-evaluations 5 -o ${PNG})
cli_bad_input(NAME convert.fit_starts_out_of_range ABSENT ${PNG}
              EXPECT "${E}command line: --fit-starts: must be in \\[1, 1000\\], got 0$"
              ARGS convert ${D}/no_such_material.json --fit-starts 0 -o ${PNG})
# a lab preset is fitted to openpbr first; one with a transmission lobe cannot be
cli_bad_input(NAME convert.lab_glass_not_fitted ABSENT ${PNG}
              EXPECT "${E}presets/glass\\.json: lobes: a mirror or transmission lobe cannot be fitted from reflectance at direction pairs"
              ARGS convert presets/glass.json --to mtlx -o ${PNG})
cli_bad_input(NAME convert.unknown_extension ABSENT ${PNG}
              EXPECT "${E}.*/convert\\.unknown_extension\\.png: unknown file extension \"\\.png\" \\(expected preset \\(\\.json\\), mtlx \\(\\.mtlx\\), gltf \\(\\.gltf\\), mitsuba \\(\\.xml\\), pbrt \\(\\.pbrt\\). or name the format with --to\\)$"
              ARGS convert presets/car_paint.json -o ${PNG})
cli_bad_input(NAME convert.unknown_format ABSENT ${PNG} EXPECT "${E}command line: --to: unknown format \"usd\""
              ARGS convert presets/car_paint.json --to usd -o ${PNG})
# a preset through MaterialX and back is the preset written directly, byte for byte
add_test(NAME cli.convert.preset_through_mtlx_unchanged
         COMMAND ${CMAKE_COMMAND} -DEXE=$<TARGET_FILE:dtoadq> -DPRESET=presets/pearlescent_paint.json -DSCRATCH=${CLI_SCRATCH}/convert
                 -P ${CLI_TEST_DIR}/convert_round_trip.cmake
         WORKING_DIRECTORY ${PROJECT_SOURCE_DIR})
set_tests_properties(cli.convert.preset_through_mtlx_unchanged PROPERTIES LABELS cli TIMEOUT 60)
