# End-to-end tests of the dtoadq command line: every kind of bad input exits non-zero with exactly
# one line naming the file and the field, and the plot commands write their files from a folder
# away from the source tree (the Python scripts are embedded). Included by tests/CMakeLists.txt.
set(CLI_TEST_DIR ${CMAKE_CURRENT_LIST_DIR})
set(CLI_SCRATCH ${CMAKE_CURRENT_BINARY_DIR}/cli_scratch)
file(MAKE_DIRECTORY ${CLI_SCRATCH})

# cli_bad_input(NAME <name> EXPECT <regex> [STDIN <file>] [ABSENT <file>] ARGS <dtoadq arguments...>)
# @PNG@ in ARGS and ABSENT stands for an output path of this test's own (tests may run in parallel).
# Runs in the source root, so presets/ and tests/cli/data/ paths are short and the messages fixed.
# EXPECT may not hold an unbalanced "[": CMake would stop splitting the argument list there.
function(cli_bad_input)
  cmake_parse_arguments(T "" "NAME;EXPECT;STDIN;ABSENT" "ARGS" ${ARGN})
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
cli_bad_input(NAME bench_brdf.presets_missing EXPECT "${E}/nonexistent-dtoadq: --presets: not a folder of presets"
              ARGS bench brdf --presets /nonexistent-dtoadq)
cli_bad_input(NAME bench_brdf.bad_preset_in_folder EXPECT "${E}${D}/[a-z_]+\\.json: "
              ARGS bench brdf --presets ${D})

cli_bad_input(NAME no_subcommand EXPECT "${E}.*subcommand"
              ARGS)

# --- the plot commands write real files, run away from the source tree ---------------------------
function(cli_output_test name min_rows pngs csvs)
  string(REPLACE ";" "|" args "${ARGN}")
  add_test(NAME cli.${name}
           COMMAND ${CMAKE_COMMAND} -DEXE=$<TARGET_FILE:dtoadq> "-DARGS=${args}" -DWORK=${CLI_SCRATCH}/${name}
                   -DPNGS=${pngs} -DCSVS=${csvs} -DMIN_ROWS=${min_rows} -P ${CLI_TEST_DIR}/expect_output.cmake)
  set_tests_properties(cli.${name} PROPERTIES LABELS cli TIMEOUT 120)
endfunction()
cli_output_test(lobe.writes_png_and_csv 16380 lobe.png lobe.csv
                lobe --material ${PROJECT_SOURCE_DIR}/presets/glossy_plastic.json --material ${PROJECT_SOURCE_DIR}/presets/frosted_glass.json
                --theta-in 40 --phi-in 15 -o lobe.png --csv lobe.csv)
cli_output_test(albedo.writes_png_and_csv 46 albedo.png albedo.csv
                albedo --material ${PROJECT_SOURCE_DIR}/presets/gold.json --strata 16 -o albedo.png --csv albedo.csv)

# --- validate and report ---------------------------------------------------------------------------
# the main job, small: every preset's lobes, albedo, validation and preview, and the preview sheet
cli_output_test(report.writes_everything 40 report/previews.png|report/albedo.png|report/preview_gold.png report/albedo.csv
                report --presets ${PROJECT_SOURCE_DIR}/presets --env ${PROJECT_SOURCE_DIR}/envmaps/studio.exr -o report
                --samples 20000 --theta-in 30 --preview-spp 2 --preview-size 96x96)
cli_bad_input(NAME validate.missing_preset EXPECT "${E}${D}/absent\\.json: cannot open preset file$"
              ARGS validate --material ${D}/absent.json)
cli_bad_input(NAME validate.too_few_samples EXPECT "${E}command line: --samples: "
              ARGS validate --samples 10 --material presets/gold.json)
cli_bad_input(NAME report.no_preset_folder EXPECT "${E}tests/cli/nope: --presets: not a folder of presets .*"
              ARGS report --presets tests/cli/nope -o ${CLI_SCRATCH}/report_none)
cli_bad_input(NAME report.bad_preset_in_folder EXPECT "${E}${D}/malformed\\.json: roughness: malformed JSON: "
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
cli_bad_input(NAME preview.unknown_sampling ABSENT ${PNG} EXPECT "${E}--ibl-sampling: unknown value \"light\" \\(brdf, env, mis\\)$"
              ARGS ${PREVIEW} --ibl-sampling light)
cli_bad_input(NAME preview.unknown_normals ABSENT ${PNG} EXPECT "${E}--normals: unknown value \"sobel\" \\(tetrahedral, central, analytic\\)$"
              ARGS ${PREVIEW} --normals sobel)
cli_bad_input(NAME preview.ground_word ABSENT ${PNG} EXPECT "${E}--ground: expected on or off, got \"maybe\"$"
              ARGS ${PREVIEW} --ground maybe)
cli_bad_input(NAME preview.unknown_tonemap ABSENT ${PNG} EXPECT "${E}--tonemap: unknown tone map \"filmic\""
              ARGS ${PREVIEW} --tonemap filmic)
cli_bad_input(NAME preview.output_extension EXPECT "${E}${CLI_SCRATCH}/preview\\.jpg: "
              ARGS preview --size 16x16 --spp 1 -o ${CLI_SCRATCH}/preview.jpg)
cli_bad_input(NAME preview.output_folder EXPECT "${E}${CLI_SCRATCH}/absent_folder/preview\\.exr: "
              ARGS preview --size 16x16 --spp 1 -o ${CLI_SCRATCH}/absent_folder/preview.exr)
cli_bad_input(NAME preview.no_device ABSENT ${PNG} EXPECT "${E}no OpenCL device matches \"no-such-device\""
              ARGS ${PREVIEW} --device no-such-device)
cli_bad_input(NAME bench_preview.bad_seconds EXPECT "${E}--seconds: must be more than 0 and at most 3600$"
              ARGS bench preview --seconds 0)

# --- preview writes a linear EXR with its metadata and an sRGB PNG beside it --------------------
add_test(NAME cli.preview.writes_exr_and_png
         COMMAND ${CMAKE_COMMAND} -DEXE=$<TARGET_FILE:dtoadq> -DWORK=${CLI_SCRATCH}/preview_output -DSOURCE=${PROJECT_SOURCE_DIR}
                 -P ${CLI_TEST_DIR}/expect_preview_output.cmake)
set_tests_properties(cli.preview.writes_exr_and_png PROPERTIES LABELS cli TIMEOUT 120)

# --- no OpenCL platform at all: the ICD loader is pointed at an empty vendor folder ---------------
file(MAKE_DIRECTORY ${CLI_SCRATCH}/no_icd_vendors)
set(NO_PLATFORM_ARGS_devices "devices")
set(NO_PLATFORM_ARGS_preview "preview|--size|8x8|--spp|1|-o|${CLI_SCRATCH}/no_platform.exr")
foreach(command devices preview)
  add_test(NAME cli.${command}.no_opencl_platform
           COMMAND ${CMAKE_COMMAND} -E env OCL_ICD_VENDORS=${CLI_SCRATCH}/no_icd_vendors
                   ${CMAKE_COMMAND} -DEXE=$<TARGET_FILE:dtoadq> "-DARGS=${NO_PLATFORM_ARGS_${command}}" -DABSENT=${CLI_SCRATCH}/no_platform.exr
                   "-DEXPECT=${E}no OpenCL device found: no platform reports a device \\(is an OpenCL driver such as pocl-opencl-icd installed\\?\\)$"
                   -P ${CLI_TEST_DIR}/expect_error.cmake
           WORKING_DIRECTORY ${PROJECT_SOURCE_DIR})
  set_tests_properties(cli.${command}.no_opencl_platform PROPERTIES LABELS cli TIMEOUT 60)
endforeach()
