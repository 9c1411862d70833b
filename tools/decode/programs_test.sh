#!/usr/bin/env bash
# SPDX-License-Identifier: BSL-1.0
# Runs the real seawire-decode and seawire-encode over examples/data and checks their output,
# errors and exit status. One ctest test per case_ function (tools/CMakeLists.txt):
#   programs_test.sh <seawire-decode> <seawire-encode> <examples/data> <case> [<registry list>]
# The registry list (tests/registry/list.cpp) prints every message seawire declares.
set -euo pipefail

decode=$1
encode=$2
data=$3
case_name=$4
registry_list=${5:-}
work=$(mktemp -d)
trap 'rm -rf -- "$work"' EXIT

families=(kingfisher sandshark robotx anello anello_mixed standard)
failures=0

fail() {
  echo "FAIL: $*" >&2
  failures=$((failures + 1))
}

# expect_eq <what> <expected> <actual>
expect_eq() {
  if [[ "$2" != "$3" ]]; then
    fail "$1"
    diff <(printf '%s\n' "$2") <(printf '%s\n' "$3") >&2 || true
  fi
}

# expect_rc <what> <expected status> <command...>: runs the command (stdout, stderr kept in
# $work/out, $work/err).
expect_rc() {
  local what=$1 want=$2
  shift 2
  local rc=0
  "$@" >"$work/out" 2>"$work/err" || rc=$?
  if [[ $rc != "$want" ]]; then
    fail "$what: exit status $rc, expected $want"
    head -c 2000 "$work/err" >&2
  fi
}

# line <n> <file>: the n-th line of a file.
line() { sed -n "${1}p" "$2"; }

crlf() { printf '%s\r\n' "$@"; }

# seal <body>: "$body*hh" with the XOR checksum of body.
seal() {
  local body=$1 x=0 i c
  for ((i = 0; i < ${#body}; i++)); do
    printf -v c '%d' "'${body:i:1}"
    x=$((x ^ c))
  done
  printf '$%s*%02X' "$body" "$x"
}

# ---------------------------------------------------------------------------------------------

case_json() {
  for f in "${families[@]}"; do
    expect_rc "decode $f.nmea" 0 "$decode" <"$data/$f.nmea"
    cp "$work/out" "$work/$f.json"
    if [[ $f != anello_mixed ]]; then  # frames are messages without a line of their own
      expect_eq "$f: one JSON object per line" "$(wc -l <"$data/$f.nmea")" \
        "$(wc -l <"$work/$f.json")"
    fi
    expect_eq "$f: nothing on stderr" "" "$(cat "$work/err")"
    if grep -qv '^{"type":"[A-Z0-9]*",' "$work/$f.json"; then fail "$f: a line without a type"; fi
  done
  local k=$work/kingfisher.json s=$work/sandshark.json r=$work/robotx.json
  local a=$work/anello.json n=$work/standard.json
  # Real vehicle lines: unpadded longitude, 7-field CPIMU, 5-field CPRBS, digits kept.
  expect_eq "CPIMU (real vehicle, 7 fields)" \
    '{"type":"CPIMU","timestamp":"16:49:58.858","rate_x_dps":-0.061035,"rate_y_dps":-0.000097,"rate_z_dps":-0.061035,"accel_x_mps2":-0.026916,"accel_y_mps2":0.104533,"accel_z_mps2":-0.932172,"nav_timestamp":null}' \
    "$(line 1 "$k")"
  expect_eq "GPRMC relayed by the vehicle" \
    '{"type":"GPRMC","time":"16:49:59.00","status":"A","latitude":42.3618523333333,"longitude":-71.0908130,"speed_knots":0.145,"course_true":156.78,"date":"2014-12-31","magnetic_variation":null,"mode":"A","navigational_status":null}' \
    "$(line 2 "$k")"
  expect_eq "GPGGA relayed by the vehicle" \
    '{"type":"GPGGA","time":"16:49:59.00","latitude":42.3618523333333,"longitude":-71.0908130,"quality":"1","satellites":6,"hdop":2.80,"altitude_m":46.6,"geoid_separation_m":-33.2,"dgps_age_s":null,"dgps_station":null}' \
    "$(line 3 "$k")"
  expect_eq "CPNVG with unpadded longitude" \
    '{"type":"CPNVG","timestamp":"16:49:59.034","latitude":42.36185236666667,"longitude":-71.0908130,"position_quality":true,"altitude_m":0,"depth_m":0,"heading_deg":234.32964,"roll_deg":-6.796959,"pitch_deg":-1.706798,"nav_timestamp":"16:49:59.006"}' \
    "$(line 4 "$k")"
  expect_eq "PYDIR" '{"type":"PYDIR","thrust_left":45,"thrust_right":55}' "$(line 7 "$k")"
  expect_eq "CPALT" '{"type":"CPALT","timestamp":"16:49:59.100","lights_on":true}' "$(line 8 "$k")"
  expect_eq "CPRBS in the vehicle's 5-field form" \
    '{"type":"CPRBS","timestamp":"16:50:04.100","battery_id":null,"stack_voltage_v":15.111097,"min_cell_voltage_v":15.107097,"max_cell_voltage_v":15.114097,"temperature_c":0}' \
    "$(grep -m1 '"CPRBS"' "$k")"
  # Sandshark: acks in their forms, mission text with spaces, the training vehicle's lines.
  expect_eq "BPLOG" '{"type":"BPLOG","code":"ACK","state":"ON"}' "$(line 3 "$s")"
  expect_eq "BFACK for a BPLOG (no command timestamp)" \
    '{"type":"BFACK","timestamp":"23:11:21.05","command":"LOG","command_timestamp":null,"behavior_id":null,"status":"2","future_use":0,"description":"","trailing":null}' \
    "$(line 4 "$s")"
  expect_eq "BFMIS Running with its log directory" \
    '{"type":"BFMIS","timestamp":"23:11:23.10","dive_file":"dive1.xml","status":"Running /var/log/mission_12","details":""}' \
    "$(grep -m1 'Running' "$s")"
  expect_eq "BFNVG from the training vehicle" \
    '{"type":"BFNVG","timestamp":"23:11:31.55","latitude":42.30000000,"longitude":-71.10000000,"position_quality":false,"altitude_m":10.0,"depth_m":1.0,"heading_deg":45.0,"roll_deg":0.0,"pitch_deg":0.0,"nav_timestamp":"23:11:31.55"}' \
    "$(grep -m1 '"23:11:31.55"' "$s")"
  expect_eq "BPSTS with spaces" \
    '{"type":"BPSTS","timestamp":"23:11:33.12","all_ok":true,"message":"BWSI Autonomy OK"}' \
    "$(grep -m1 '"23:11:33.12"' "$s")"
  expect_eq "BPRMB with blanks" \
    '{"type":"BPRMB","timestamp":"23:11:37.32","heading":null,"depth":null,"depth_mode":null,"speed":750,"speed_mode":"0","horizontal_mode":"1"}' \
    "$(grep -m1 '"BPRMB","timestamp":"23:11:37.32"' "$s")"
  expect_eq "BFACK without a description (6 fields)" \
    '{"type":"BFACK","timestamp":"23:12:05.100","command":"RMB","command_timestamp":"23:12:04.72","behavior_id":null,"status":"2","future_use":0,"description":null,"trailing":null}' \
    "$(grep -m1 '"23:12:05.100"' "$s")"
  # RobotX: the spec's five reports, decimal-degree positions signed.
  expect_eq "RXHRB" \
    '{"type":"RXHRB","date":"2018-12-10","time":"16:12:29","latitude":21.31198,"longitude":-157.88972,"team_id":"AUVSI","system_mode":"2","auv_status":"1"}' \
    "$(line 1 "$r")"
  expect_eq "RXGAT" \
    '{"type":"RXGAT","date":"2018-12-10","time":"16:12:29","team_id":"AUVSI","entrance_gate":"1","exit_gate":"2","light_buoy_active":"Y","light_pattern":"RGB"}' \
    "$(line 2 "$r")"
  expect_eq "RXDOK" \
    '{"type":"RXDOK","date":"2018-12-10","time":"16:12:29","team_id":"AUVSI","shape_color":"R","shape":"TRIAN"}' \
    "$(line 4 "$r")"
  expect_eq "RXGAT with the light buoy off (no pattern)" \
    '{"type":"RXGAT","date":"2018-12-10","time":"16:12:35","team_id":"AUVSI","entrance_gate":"2","exit_gate":"3","light_buoy_active":"N","light_pattern":null}' \
    "$(grep -m1 '"16:12:35","team_id"' "$r")"
  # ANELLO inputs, any talker.
  expect_eq "PAPGPSCTRL" '{"type":"PAPGPSCTRL","control":"1"}' "$(line 1 "$a")"
  expect_eq "VMVBW" \
    '{"type":"VMVBW","longitudinal_water_knots":0.0,"transverse_water_knots":0.0,"water_status":"A","longitudinal_ground_knots":0.0,"transverse_ground_knots":0.0,"ground_status":"A","stern_transverse_water_knots":null,"stern_water_status":null,"stern_transverse_ground_knots":null,"stern_ground_status":null}' \
    "$(line 2 "$a")"
  expect_eq "VWVHW with a blank magnetic heading" \
    '{"type":"VWVHW","heading_true_deg":88.5,"heading_magnetic_deg":null,"speed_knots":0.29,"speed_kmh":0.54}' \
    "$(line 3 "$a")"
  # Standard: no fix yet, and sentences seawire does not decode.
  expect_eq "RMC without a fix" \
    '{"type":"GPRMC","time":null,"status":"V","latitude":null,"longitude":null,"speed_knots":null,"course_true":null,"date":null,"magnetic_variation":null,"mode":"N","navigational_status":null}' \
    "$(line 1 "$n")"
  expect_eq "unknown but well-formed: type and fields" \
    '{"type":"GPGSA","fields":["A","3","04","05","","09","12","","","24","","","","","2.5","1.3","2.1"]}' \
    "$(line 6 "$n")"
  expect_eq "RMC 2.2 with magnetic variation" \
    '"magnetic_variation":15.3,"mode":null,"navigational_status":null}' \
    "$(line 4 "$n" | grep -o '"magnetic_variation".*')"
  expect_eq "RMC 4.1 from GN" '"mode":"A","navigational_status":"V"}' \
    "$(grep -m1 '"GNRMC"' "$n" | grep -o '"mode".*')"
  expect_eq "HDT from a settling gyrocompass, then with a heading" \
    '{"type":"HEHDT","heading_true_deg":null}
{"type":"HEHDT","heading_true_deg":309.79}' "$(grep -m2 '"HEHDT"' "$n")"
}

case_bad() {
  expect_rc "decode bad.nmea" 1 "$decode" <"$data/bad.nmea"
  local o=$work/out
  expect_eq "bad.nmea: 14 lines, 15 outputs (line 12 holds a good PYDIR)" 15 "$(wc -l <"$o")"
  expect_eq "stderr empty in JSON mode" "" "$(cat "$work/err")"
  # line: error, field -- each rejected line of bad.nmea.
  local expected=(
    '2:checksum_mismatch:0' '3:checksum_mismatch:0' '4:checksum_mismatch:0'
    '5:minute_out_of_range:2' '6:too_few_fields:6' '7:missing_start:0' '8:bad_enum:1'
    '9:out_of_range:1' '10:bad_character:0' '11:bad_length:7' '12:truncated:0'
    '13:bad_enum:2')
  expect_eq "bad.nmea: line, error and field of every rejected line" \
    "$(printf '%s\n' "${expected[@]}")" \
    "$(sed -n 's/^{"line":\([0-9]*\),"error":"\([a-z_]*\)","field":\([0-9]*\),.*/\1:\2:\3/p' "$o")"
  expect_eq "checksum error in full" \
    '{"line":2,"error":"checksum_mismatch","field":0,"detail":"checksum does not match the sentence (sent 5B, computed 4E) at column 83","input":"$BFNVG,081025.987,4221.81092,N,07106.84603,W,1,45.3,20.1,203.1,-3.4,4.5,081025.980*5B"}' \
    "$(line 2 "$o")"
  expect_eq "field error in full" \
    '{"line":5,"error":"minute_out_of_range","field":2,"detail":"CPNVG field 2 (latitude) \"4261.81092\": minutes out of range (00-59)","input":"$CPNVG,081025.987,4261.81092,N,07106.84603,W,1,0,0,203.1,-3.4,4.5,081025.980*5C"}' \
    "$(line 5 "$o")"
  expect_eq "garbage line" \
    '{"line":7,"error":"missing_start","field":0,"detail":"24 bytes outside any sentence or frame (no '"'"'$'"'"' or '"'"'!'"'"' before them); dropped","input":"### vehicle rebooted ###"}' \
    "$(line 7 "$o")"
  expect_eq "a control byte, escaped in the report" \
    '"input":"$CPNVR,164959.063,0.029\u000141,-0.068552,0,0.060938,0,-0.061132*59"}' \
    "$(line 10 "$o" | grep -o '"input".*')"
  expect_eq "an interrupted sentence: only its own bytes shown" \
    '{"line":12,"error":"truncated","field":0,"detail":"a sentence without a complete checksum, ended by the next '"'"'$'"'"' or 0xAB before its line ending (cut short, or sent without either); 25 bytes dropped","input":"$CPRCM,164959.065,0,234.3"}' \
    "$(line 12 "$o")"
  expect_eq "the sentence after an interrupted one still decodes, after the report" \
    '{"type":"PYDIR","thrust_left":45,"thrust_right":55}' "$(line 13 "$o")"
  expect_eq "good lines around the bad ones" "$(line 1 "$o")" "$(line 15 "$o")"
}

case_nmea() {
  for f in "${families[@]}"; do
    expect_rc "decode --format nmea $f.nmea" 0 "$decode" --format nmea <"$data/$f.nmea"
    if ! cmp -s "$work/out" "$data/$f.nmea"; then fail "$f: --format nmea is not byte-exact"; fi
  done
  expect_rc "decode --format nmea bad.nmea" 1 "$decode" --format nmea <"$data/bad.nmea"
  expect_eq "bad.nmea: only the good sentences on stdout" \
    "$(crlf "$(line 1 "$data/bad.nmea" | tr -d '\r')" '$PYDIR,45,55*57' \
      "$(line 14 "$data/bad.nmea" | tr -d '\r')")" "$(cat "$work/out")"
  expect_eq "bad.nmea: one reason per rejected line on stderr" 12 "$(wc -l <"$work/err")"
  expect_eq "stderr names line and reason" \
    'seawire-decode: line 5: minute_out_of_range: CPNVG field 2 (latitude) "4261.81092": minutes out of range (00-59)' \
    "$(line 4 "$work/err")"
  # Liberal input comes out canonical: uppercase checksum, CR LF, checksum added.
  local plus foo
  plus=$(seal 'PYDIR,+45,55')
  foo=$(seal 'XXFOO,1,,2')
  printf '$BPLOG,ACK,ON*1e\n$PYDIR,45,55\r\n%s\r\n%s\r\n' "$plus" "${foo%??}$(tr A-F a-f <<<"${foo: -2}")" >"$work/in"
  expect_rc "decode --format nmea, liberal input" 0 "$decode" --format nmea <"$work/in"
  expect_eq "canonical output" "$(crlf '$BPLOG,ACK,ON*1E' '$PYDIR,45,55*57' '$PYDIR,45,55*57' \
    "$foo")" "$(cat "$work/out")"
  # Fields that may be left out but came blank go back blank: the spec's eight-field CPIMU, RMC
  # 2.3/4.1 with a blank mode or status, VBW with blank NMEA 3.0 stern fields, the spec's
  # six-field CPRBS with a blank battery id.
  crlf "$(seal 'CPIMU,164958.858,-0.061035,-0.000097,-0.061035,-0.026916,0.104533,-0.932172,')" \
    "$(seal 'GPRMC,164959.00,A,4221.71114,N,07105.44878,W,0.145,156.78,311214,,,')" \
    "$(seal 'GNRMC,120000.00,V,,,,,,,290224,,,,')" \
    "$(seal 'VDVBW,4.91,-0.12,A,5.02,0.08,A,,,,')" "$(seal 'CPRBS,105707.24,,15.2,15.1,15.3,0')" \
    >"$work/in"
  expect_rc "decode --format nmea, blank trailing fields" 0 "$decode" --format nmea <"$work/in"
  if ! cmp -s "$work/out" "$work/in"; then fail "blank trailing fields not written back as they came"; fi
}

case_none() {
  for f in "${families[@]}"; do
    expect_rc "decode --format none $f.nmea" 0 "$decode" --format none <"$data/$f.nmea"
    expect_eq "$f: --format none writes nothing" "" "$(cat "$work/out" "$work/err")"
  done
  expect_rc "decode --format none bad.nmea" 1 "$decode" --format none <"$data/bad.nmea"
  expect_eq "--format none: nothing on stdout" "" "$(cat "$work/out")"
  expect_eq "--format none: 12 reasons on stderr" 12 "$(wc -l <"$work/err")"
  expect_rc "decode --stats" 1 "$decode" --format none --stats <"$data/bad.nmea"
  local err
  err=$(cat "$work/err")
  for want in 'seawire-decode: 3 messages decoded, 12 rejected' 'by type:' \
    'GPRMC                2' 'PYDIR                1' 'by error:' 'checksum_mismatch    3' \
    'missing_start        1' 'input: 12 sentences, 0 frames; 24 noise bytes, 87 dropped bytes; 1 sentences interrupted, 0 overlong, 1 with invalid bytes'; do
    if [[ $err != *"$want"* ]]; then fail "--stats: no '$want' in: $err"; fi
  done
  expect_rc "decode --stats, all good" 0 "$decode" --stats <"$data/robotx.nmea"
  if ! grep -q 'RXHRB  *27' "$work/err"; then fail "--stats: RXHRB count"; fi
}

case_roundtrip() {
  for f in "${families[@]}"; do
    "$decode" <"$data/$f.nmea" >"$work/$f.json"
    expect_rc "encode $f" 0 "$encode" <"$work/$f.json"
    cp "$work/out" "$work/$f.again"
    expect_rc "decode the re-encoded $f" 0 "$decode" <"$work/$f.again"
    if ! cmp -s "$work/out" "$work/$f.json"; then fail "$f: decode | encode changed the meaning"; fi
    if [[ $f != kingfisher && $f != anello_mixed ]] && ! cmp -s "$work/$f.again" "$data/$f.nmea"; then
      fail "$f: decode | encode is not byte-exact"
    fi
  done
  # The sample logs hold every sentence and frame of the registry ("--" is any talker; the PGNs
  # have logs of their own), so the round trip covers them all.
  local type missing=() types
  types=$("$registry_list" | sed -e '/^PGN /d' -e 's/^--/../' -e 's/^frame$/AB00/')
  if [[ $(wc -l <<<"$types") -lt 30 ]]; then fail "the registry lists too few messages: $types"; fi
  for type in $types; do
    grep -q "^{\"type\":\"$type\"," "$work"/*.json || missing+=("$type")
  done
  expect_eq "every message type in the sample logs" "" "${missing[*]}"
  # Kingfisher: the only difference is the vehicle's unpadded longitude degrees.
  expect_eq "kingfisher: padded longitude is the only change" \
    "$(sed 's/,\([0-9]\{4\}\.[0-9]*\),W,/,0\1,W,/' "$data/kingfisher.nmea" | tr -d '\r' | cut -d'*' -f1)" \
    "$(tr -d '\r' <"$work/kingfisher.again" | cut -d'*' -f1)"
  # ANELLO: only the spec's example frame changes, whose air temperature 0xFFFF ("not available" in the
  # spec's own example) is sent as the spec's 0x7FFF: the frame's byte 52 and its CRC (4-7),
  # counted from 1 in the file (the frame follows an 18-byte sentence).
  expect_eq "anello_mixed: only the spec's example frame's air temperature and CRC differ" \
    "23 24 25 26 71" \
    "$(cmp -l "$work/anello_mixed.again" "$data/anello_mixed.nmea" | awk '{printf "%s ", $1}' |
      sed 's/ $//')"
  # Error objects from decode are passed over by encode.
  "$decode" <"$data/bad.nmea" >"$work/bad.json" || true
  expect_rc "encode decode's output of bad.nmea" 0 "$encode" <"$work/bad.json"
  expect_eq "only the good sentences come back" "$(crlf "$(line 1 "$data/bad.nmea" | tr -d '\r')" \
    '$PYDIR,45,55*57' "$(line 14 "$data/bad.nmea" | tr -d '\r')")" "$(cat "$work/out")"
  # docs/round-trip.md: what --format nmea keeps and what it writes in the standard form.
  local rmc='GPRMC,164959.00,A,4221.71114,N,07105.44878,W,0.011,,311214,'
  local kept=("$(seal 'IIVHW,,T,,M,5.2,N,9.6,K')" "$(seal "$rmc,E,A")" "$(seal "$rmc,W")"
    "$(seal 'IIVHW,,,211.0,M,5.2,N,,')" "$(seal 'GPGGA,092725.00,,,,,0,00,99.99,,,,,,')")
  crlf "${kept[@]}" "$(seal "${rmc}999.9,E,A")" "$(seal 'IIVHW,,,211.0,,5.2,N,,')" >"$work/in"
  expect_rc "--strict takes these forms" 0 "$decode" --strict --format none <"$work/in"
  expect_rc "--format nmea" 0 "$decode" --format nmea <"$work/in"
  expect_eq "kept as they came, or written in the listed standard form" \
    "$(crlf "${kept[@]}" "$(seal "$rmc,E,A")" "$(seal 'IIVHW,,,211.0,M,5.2,N,,')")" \
    "$(cat "$work/out")"
  expect_rc "decode | encode" 0 "$encode" < <("$decode" <"$work/in")
  expect_eq "through JSON a variation letter without a value is null, as no variation is" \
    "$(seal "$rmc,,A")" "$(line 2 "$work/out" | tr -d '\r')"
  expect_eq "through JSON the unit letters of blank values are written" \
    "$(seal 'IIVHW,,T,211.0,M,5.2,N,,K')" "$(line 4 "$work/out" | tr -d '\r')"
}

case_options() {
  # seawire-encode numbers a CPRBS field in the form it writes (no battery_id: five fields).
  printf '%s\n' '{"type":"CPRBS","timestamp":"17:29:09.322","stack_voltage_v":15.1,"min_cell_voltage_v":15.1,"max_cell_voltage_v":15.2,"temperature_c":"warm"}' \
    '{"type":"CPRBS","timestamp":"17:29:09.322","battery_id":1,"stack_voltage_v":15.1,"min_cell_voltage_v":15.1,"max_cell_voltage_v":15.2,"temperature_c":"warm"}' \
    >"$work/in"
  expect_rc "encode CPRBS, both forms" 1 "$encode" <"$work/in"
  expect_eq "temperature is field 5 of the short form, 6 of the long" \
    "$(printf '%s\n' 'line 1: CPRBS field 5 (temperature_c)' 'line 2: CPRBS field 6 (temperature_c)')" \
    "$(sed 's/^seawire-encode: \(line [0-9]*: CPRBS field [0-9] ([a-z_]*)\).*/\1/' "$work/err")"
  # A position without a fraction: read by default, refused under --strict.
  crlf "$(seal GPRMC,164959.00,A,4221,N,07105.44878,W,0.145,156.78,311214,,,A)" >"$work/in"
  expect_rc "position without a fraction" 0 "$decode" --format none <"$work/in"
  expect_rc "position without a fraction, --strict" 1 "$decode" --strict --format none <"$work/in"
  expect_eq "--strict: the latitude" 'line 1: bad_latitude: GPRMC field 3 (latitude) "4221"' \
    "$(sed 's/^seawire-decode: \(line [0-9]*: [a-z_]*: [^:]*\):.*/\1/' "$work/err")"
  # The five-field CPRBS (no battery id): errors name the field as it is on the wire.
  crlf "$(seal CPRBS,172909.322,15.1,15.1,15.1,x)" "$(seal CPRBS,172909.322,1,15.1,15.1,x,0)" \
    >"$work/in"
  expect_rc "CPRBS, both forms" 1 "$decode" --format none <"$work/in"
  expect_eq "field 5 of the short form is the temperature, of the long one the max cell voltage" \
    "$(printf '%s\n' 'line 1: CPRBS field 5 (temperature_c)' 'line 2: CPRBS field 5 (max_cell_voltage_v)')" \
    "$(sed 's/^seawire-decode: \(line [0-9]*\): bad_number: \(.*)\) .*/\1: \2/' "$work/err")"
  printf '$PYDIR,45,55\r\n' >"$work/in"
  expect_rc "no checksum, default" 0 "$decode" <"$work/in"
  expect_rc "no checksum, --checksum required" 1 "$decode" --checksum required <"$work/in"
  expect_eq "missing_checksum" '{"line":1,"error":"missing_checksum","field":0,"detail":"checksum required but missing at column 12","input":"$PYDIR,45,55"}' \
    "$(cat "$work/out")"
  printf '$PYDIR,45,55*00\r\n' >"$work/in"
  expect_rc "wrong checksum, --checksum ignore" 0 "$decode" -c ignore <"$work/in"
  expect_eq "decoded anyway" '{"type":"PYDIR","thrust_left":45,"thrust_right":55}' "$(cat "$work/out")"
  printf '$BPLOG,ACK,ON*1e\r\n$PYDIR,45,55*57\n%s\r\n$PYDIR,45,55\r\n$PYDIR,45,55*57\r\n' \
    "$(seal 'PYDIR,+45,55')" >"$work/in"
  expect_rc "--strict" 1 "$decode" --strict --format none <"$work/in"
  expect_eq "--strict rejects lowercase hex, LF alone, '+' and a missing checksum" \
    "$(printf '%s\n' 'line 1: bad_checksum_format' 'line 2: bad_line_ending' 'line 3: bad_number' \
      'line 4: missing_checksum')" "$(sed 's/^seawire-decode: \(line [0-9]*: [a-z_]*\):.*/\1/' "$work/err")"
  # SPI 4.2: spaces may come before a number's minus sign; --strict refuses them.
  printf '%s\r\n' "$(seal 'BPRMB,231204.72, -15,,,750,0,1')" >"$work/in"
  expect_rc "spaces around a number" 0 "$decode" <"$work/in"
  expect_eq "spaces are not part of the number" \
    '{"type":"BPRMB","timestamp":"23:12:04.72","heading":-15,"depth":null,"depth_mode":null,"speed":750,"speed_mode":"0","horizontal_mode":"1"}' \
    "$(cat "$work/out")"
  expect_rc "spaces around a number, --strict" 1 "$decode" --strict <"$work/in"
  printf '$PYDIR,45,55\r\n' >"$work/in"
  expect_rc "--strict --checksum verify" 0 "$decode" --strict --checksum verify <"$work/in"
  # A checksum that is not checked has no case either; one that is verified keeps --strict's.
  printf '$BPLOG,ACK,ON*1e\r\n$BPLOG,ACK,ON*0f\r\n$PYDIR,45,55*5a\r\n' >"$work/in"
  expect_rc "--strict --checksum ignore, lowercase hex" 0 "$decode" --strict --checksum ignore <"$work/in"
  expect_eq "lowercase checksums, right or wrong, are not checked" "$(printf '%s\n' \
    '{"type":"BPLOG","code":"ACK","state":"ON"}' '{"type":"BPLOG","code":"ACK","state":"ON"}' \
    '{"type":"PYDIR","thrust_left":45,"thrust_right":55}')" "$(cat "$work/out")"
  expect_rc "--strict --checksum verify, lowercase hex" 1 "$decode" --strict --checksum verify \
    --format none <"$work/in"
  expect_eq "a verified checksum is still uppercase under --strict" \
    "$(printf '%s\n' 'line 1: bad_checksum_format' 'line 2: bad_checksum_format' 'line 3: bad_checksum_format')" \
    "$(sed 's/^seawire-decode: \(line [0-9]*: [a-z_]*\):.*/\1/' "$work/err")"
  printf '$BPLOG,ACK,ON*1\r\n$BPLOG,ACK,ON*1g\r\n' >"$work/in"
  expect_rc "--checksum ignore, not two hex digits" 1 "$decode" --checksum ignore --format none <"$work/in"
  expect_eq "what follows '*' must still be two hex digits" \
    "$(printf '%s\n' 'line 1: bad_checksum_format' 'line 2: bad_checksum_format')" \
    "$(sed 's/^seawire-decode: \(line [0-9]*: [a-z_]*\):.*/\1/' "$work/err")"
  expect_rc "--line-buffered" 0 "$decode" --line-buffered <"$data/sandshark.nmea"
  if ! cmp -s "$work/out" <("$decode" <"$data/sandshark.nmea"); then
    fail "--line-buffered changes the output"
  fi
  # A sentence split across read() chunks and lines of every ending.
  {
    head -c 70000 /dev/zero | tr '\0' ' '
    printf '\n%s\r%s\n%s' "$(seal PYDIR,1,2)" "$(seal PYDIR,3,4)" "$(seal PYDIR,5,6)"
  } >"$work/in"
  expect_rc "long noise line, CR and LF endings, no final ending" 1 "$decode" <"$work/in"
  expect_eq "noise reported once, then three commands" \
    "$(printf '%s\n' 1:missing_start '{"type":"PYDIR","thrust_left":1,"thrust_right":2}' \
      '{"type":"PYDIR","thrust_left":3,"thrust_right":4}' '{"type":"PYDIR","thrust_left":5,"thrust_right":6}')" \
    "$(sed 's/^{"line":\([0-9]*\),"error":"\([a-z_]*\)".*/\1:\2/' "$work/out")"
}

# What the stream reader drops is reported where it happened, in order with the messages,
# whatever the line endings and however read() cuts the input.
case_drops() {
  local a b c d
  a=$(seal PYDIR,1,2) b=$(seal PYDIR,3,4) c=$(seal PYDIR,5,6) d=$(seal PYDIR,7,8)
  local summary=(sed -e 's/^{"line":\([0-9]*\),"error":"\([a-z_]*\)".*/\1:\2/'
    -e 's/^{"type":"PYDIR","thrust_left":\([0-9]*\).*/PYDIR \1/')
  # CR-only line endings: the junk is on line 2, the interrupted sentence on line 4.
  printf '%s\r### junk\r%s\r$CPRCM,1%s\r' "$a" "$b" "$c" >"$work/in"
  expect_rc "CR line endings" 1 "$decode" <"$work/in"
  expect_eq "CR line endings: each report on its own line, in order" \
    "$(printf '%s\n' 'PYDIR 1' 2:missing_start 'PYDIR 3' 4:truncated 'PYDIR 5')" \
    "$("${summary[@]}" "$work/out")"
  expect_eq "noise shows only its own bytes" '"input":"### junk"}' \
    "$(line 2 "$work/out" | grep -o '"input".*')"
  # A false frame start (AB 00 00 30) swallows the next 52 bytes; its CRC fails, the bytes
  # after the AB are read again and the sentences in them come out, after the report.
  { hex2bin AB000030; crlf "$a" "$b" "$c" "$d"; } >"$work/in"
  expect_rc "false frame start" 1 "$decode" <"$work/in"
  expect_eq "false frame start: reported once (its 00 00 30 with it), then every sentence" \
    "$(printf '%s\n' 1:crc_mismatch 'PYDIR 1' 'PYDIR 3' 'PYDIR 5' 'PYDIR 7')" \
    "$("${summary[@]}" "$work/out")"
  local shown start
  shown=$(line 1 "$work/out" | grep -o '"input":"[0-9A-F]*"' | cut -d'"' -f4)
  start=AB000030$(crlf "$a" | od -An -tx1 | tr -d ' \n' | tr a-f A-F)
  expect_eq "the 56-byte candidate shown in hex" "112 $start" "${#shown} ${shown:0:${#start}}"
  # Noise after a rejected candidate, beyond its 56 bytes, is a report of its own.
  { hex2bin AB000030; crlf "$a" "$b" "$c" "$d" "junk"; } >"$work/in"
  expect_rc "false frame start, then junk" 1 "$decode" <"$work/in"
  expect_eq "the junk past the candidate reported on its own line" \
    "$(printf '%s\n' 1:crc_mismatch 'PYDIR 1' 'PYDIR 3' 'PYDIR 5' 'PYDIR 7' 5:missing_start)" \
    "$("${summary[@]}" "$work/out")"
  # A wrong length: one report showing the header and the length byte; a lone AB in noise is
  # part of that noise.
  { hex2bin AB000031; printf '\r\nab'; hex2bin AB; printf 'cd\r\n%s\r\n' "$a"; } >"$work/in"
  expect_rc "bad length, lone AB" 1 "$decode" <"$work/in"
  expect_eq "one report each, then the sentence" \
    "$(printf '%s\n' '1 bad_length AB000031' '2 missing_start ab\u00ABcd' 'PYDIR 1')" \
    "$(sed -e 's/^{"line":\([0-9]*\),"error":"\([a-z_]*\)".*"input":"\(.*\)"}$/\1 \2 \3/' \
      -e 's/^{"type":"PYDIR","thrust_left":\([0-9]*\).*/PYDIR \1/' "$work/out")"
  # An overlong sentence across read() chunks (64 KiB), then a good one on the next line.
  {
    printf '$PYDIR,'
    head -c 70000 /dev/zero | tr '\0' 9
    printf '\r\n%s\r\n' "$b"
  } >"$work/in"
  expect_rc "overlong sentence" 1 "$decode" <"$work/in"
  expect_eq "overlong: one report, then the next line" "$(printf '%s\n' 1:too_long 'PYDIR 3')" \
    "$("${summary[@]}" "$work/out")"
  expect_eq "overlong: the whole line counted, its start shown" \
    "a sentence longer than 1024 bytes; 70007 bytes dropped up to the line's end 256" \
    "$(line 1 "$work/out" | sed 's/.*"detail":"\([^"]*\)","input":"\([^"]*\)".*/\1 \2/' |
      awk '{ n = length($NF); $NF = ""; print $0 n }')"
  # A bad byte after a chunk boundary, then a frame on the same line.
  {
    head -c 65530 /dev/zero | tr '\0' ' '
    printf '%s\r\n$PYDIR,1\001,2*00' "$a"
    hex2bin "$seed_frame"
    printf '\r\n'
  } >"$work/in"
  expect_rc "bad byte across a chunk boundary" 1 "$decode" <"$work/in"
  expect_eq "noise, the sentence, the bad line, then the frame on line 2" \
    "$(printf '%s\n' 1:missing_start 'PYDIR 1' 2:bad_character AB00)" \
    "$("${summary[@]}" -e 's/^{"type":"AB00".*/AB00/' "$work/out")"
  expect_eq "--format none: the same reports on stderr" \
    "$(printf '%s\n' 'line 1: missing_start' 'line 2: bad_character')" \
    "$("$decode" --format none <"$work/in" 2>&1 | sed 's/^seawire-decode: \(line [0-9]*: [a-z_]*\):.*/\1/')"
  # A '$' right after a whole "*hh": nothing was cut, only the line ending is missing. Both
  # sentences decode; --strict says what is wrong with the first.
  printf '%s%s\r\n%s%s' "$a" "$b" "$c" "$d" >"$work/in"
  expect_rc "no line ending between sentences" 0 "$decode" <"$work/in"
  expect_eq "no line ending between sentences: every sentence decoded" \
    "$(printf '%s\n' 'PYDIR 1' 'PYDIR 3' 'PYDIR 5' 'PYDIR 7')" "$("${summary[@]}" "$work/out")"
  expect_rc "no line ending between sentences, --strict" 1 "$decode" --strict <"$work/in"
  expect_eq "--strict: the missing line endings named, the others decoded" \
    "$(printf '%s\n' 1:bad_line_ending 'PYDIR 3' 2:bad_line_ending 2:bad_line_ending)" \
    "$("${summary[@]}" "$work/out")"
  expect_eq "--strict: what the line ends in" \
    '"detail":"line does not end in CR LF: it has no line ending","input":"'"$a"'"}' \
    "$(line 1 "$work/out" | grep -o '"detail".*')"
  # A sentence cut inside its checksum, or sent without one, may have lost its tail: dropped,
  # and the next one still read.
  printf '%s%s\r\n' "${a%?}" "$b" >"$work/in"
  expect_rc "a checksum cut by the next '\$'" 1 "$decode" <"$work/in"
  expect_eq "a checksum cut by the next '\$': only its own bytes dropped" \
    "$(printf '%s\n' 1:truncated 'PYDIR 3')" "$("${summary[@]}" "$work/out")"
  # After the checksum only the line ending may stand.
  printf '%s \r\n%sX\r\n%s*\r\n%s\r\n' "$a" "$b" "$c" "$d" >"$work/in"
  expect_rc "characters after the checksum" 1 "$decode" <"$work/in"
  expect_eq "characters after the checksum, named and shown" \
    "$(printf '%s\n' \
      '{"line":1,"error":"trailing_characters","field":0,"detail":"unexpected characters after the checksum (\" \") at column 13","input":"'"$a"' "}' \
      '{"line":2,"error":"trailing_characters","field":0,"detail":"unexpected characters after the checksum (\"X\") at column 13","input":"'"$b"'X"}' \
      '{"line":3,"error":"trailing_characters","field":0,"detail":"unexpected characters after the checksum (\"*\") at column 13","input":"'"$c"'*"}' \
      '{"type":"PYDIR","thrust_left":7,"thrust_right":8}')" "$(cat "$work/out")"
}

# hex2bin <hex>: the bytes.
hex2bin() { printf "$(sed 's/../\\x&/g' <<<"$1")"; }

# crc32 <hex>: zlib's CRC-32 of the bytes, as 8 uppercase hex digits.
crc32() {
  local hex=$1 crc=0xFFFFFFFF i k
  for ((i = 0; i < ${#hex}; i += 2)); do
    crc=$((crc ^ 16#${hex:i:2}))
    for ((k = 0; k < 8; k++)); do crc=$(((crc >> 1) ^ (0xEDB88320 & -(crc & 1)))); done
  done
  printf '%08X' $((crc ^ 0xFFFFFFFF))
}

# frame <payload hex>: the 56-byte AB00 frame around a 48-byte payload, as hex.
frame() { printf 'AB000030%s%s' "$(crc32 "$1")" "$1"; }

# set_field <payload hex> <hex offset> <hex value>: the payload with the value written there.
set_field() { printf '%s%s%s' "${1:0:$2}" "$3" "${1:$2+${#3}}"; }
seed_frame=AB0000308EF7F176005901F4ECFFF903369A0000FFFF00000190794363D0000001E07FFFFFFFFFFF000000000002006C0003005AFFFFFFFF

case_frames() {
  local m=$work/anello_mixed.json
  expect_rc "decode anello_mixed.nmea" 0 "$decode" <"$data/anello_mixed.nmea"
  cp "$work/out" "$m"
  expect_eq "43 frames and 125 sentences" "43 125" \
    "$(grep -c '"type":"AB00"' "$m") $(grep -vc '"type":"AB00"' "$m")"
  expect_eq "the spec's example frame, after the first sentence" \
    '{"type":"AB00","heading_deg":89,"latitude":32.828671,"longitude":-117.229926,"sog_mps":0.0,"cog_deg":null,"gps_time":"2024-07-03T15:42:58.000Z","alt_msl_m":48.0,"geoid_sep_m":null,"hdop":null,"fix_quality":null,"motor_pct":0,"rudder_pct":0,"stw_mps":0.0,"wind_speed_abs_mps":0.2,"wind_dir_abs_deg":108,"wind_speed_rel_mps":0.3,"wind_dir_rel_deg":90,"air_temp_c":null,"pressure_hpa":null}' \
    "$(line 2 "$m")"
  expect_eq "a frame holding '$', CR and LF bytes" \
    '{"type":"AB00","heading_deg":36,"latitude":10.487844,"longitude":-0.000013,"sog_mps":1.0,"cog_deg":13,' \
    "$(tail -n 2 "$m" | head -n 1 | cut -d, -f1-6),"
  # A frame with a bad CRC between two sentences: reported, and the next sentence still read.
  local bad=${seed_frame:0:20}FF${seed_frame:22}
  {
    crlf "$(seal PYDIR,1,2)"
    hex2bin "$bad"
    crlf "$(seal PYDIR,3,4)"
    hex2bin "$seed_frame"
  } >"$work/in"
  expect_rc "a frame with a bad CRC" 1 "$decode" <"$work/in"
  expect_eq "reported on its line, then the sentence after it, then a good frame" \
    "$(printf '%s\n' '{"type":"PYDIR","thrust_left":1,"thrust_right":2}' 2:crc_mismatch \
      '{"type":"PYDIR","thrust_left":3,"thrust_right":4}' AB00)" \
    "$(sed -e 's/^{"line":\([0-9]*\),"error":"\([a-z_]*\)".*/\1:\2/' \
      -e 's/^{"type":"AB00".*/AB00/' "$work/out")"
  expect_rc "--format nmea with frames" 1 "$decode" --format nmea <"$work/in"
  if ! cmp -s "$work/out" <({ crlf "$(seal PYDIR,1,2)" "$(seal PYDIR,3,4)"; hex2bin "$seed_frame"; }); then
    fail "--format nmea: frames written back as 56 bytes"
  fi
  # seawire-encode writes frames; "not available" as the spec's maximum.
  printf '%s\n' '{"type":"AB00","heading_deg":89,"latitude":32.828671,"longitude":-117.229926,"sog_mps":0.0,"gps_time":"2024-07-03T15:42:58.000Z","alt_msl_m":48.0,"motor_pct":0,"rudder_pct":0,"stw_mps":0.0,"wind_speed_abs_mps":0.2,"wind_dir_abs_deg":108,"wind_speed_rel_mps":0.3,"wind_dir_rel_deg":90}' \
    '{"type":"AB00","heading_deg":361}' '{"type":"AB00","latitude_deg":1}' >"$work/in"
  expect_rc "encode frames" 1 "$encode" <"$work/in"
  expect_eq "one frame of 56 bytes, AB 00 00 30 ..." "56 ab000030" \
    "$(wc -c <"$work/out") $(head -c 4 "$work/out" | od -An -tx1 | tr -d ' \n')"
  expect_eq "the frame's payload is the spec's, but for the air temperature" \
    "${seed_frame:16:88}7FFFFFFF" "$(tail -c 48 "$work/out" | od -An -tx1 | tr -d ' \n' | tr a-f A-F)"
  expect_eq "frame errors name the field" "$(printf '%s\n' \
    'seawire-encode: line 2: AB00 field 1 (heading_deg) 361: out_of_range: value outside the range the spec allows' \
    'seawire-encode: line 3: AB00: unknown key "latitude_deg" (not a field of AB00)')" "$(cat "$work/err")"
  # A measured value is rounded to the field's resolution; a code (the GGA fix quality) is not.
  printf '%s\n' '{"type":"AB00","heading_deg":89.5,"sog_mps":1.25,"fix_quality":7}' \
    '{"type":"AB00","fix_quality":7.5}' '{"type":"AB00","fix_quality":7.0}' \
    '{"type":"AB00","precision":{"latitude":3}}' >"$work/in"
  expect_rc "encode frames with fractions" 1 "$encode" <"$work/in"
  expect_eq "heading 89.5 sent as 90, SOG 1.25 as 1.3, fix quality 7" "90 1.3 7" \
    "$("$decode" <"$work/out" | sed 's/.*"heading_deg":\([^,]*\),.*"sog_mps":\([^,]*\),.*"fix_quality":\([^,]*\),.*/\1 \2 \3/')"
  expect_eq "a fix quality with a fraction is refused; frames take no precision" "$(printf '%s\n' \
    'seawire-encode: line 2: AB00 field 10 (fix_quality) 7.5: bad_number: not a number of the field'"'"'s form (a code: a whole number, not rounded)' \
    'seawire-encode: line 3: AB00 field 10 (fix_quality) 7.0: bad_number: not a number of the field'"'"'s form (a code: a whole number, not rounded)' \
    'seawire-encode: line 4: AB00: unknown key "precision" (not a field of AB00)')" "$(cat "$work/err")"
}

# seawire-decode holds frames to the spec's ranges (as sentences), without --strict: whatever it
# decodes, seawire-encode sends back unchanged.
case_frame_ranges() {
  local seed=${seed_frame:16} spec h bad=() good=()
  # Payload offsets in hex digits: heading 0, latitude 4, longitude 12, SOG 20, COG 24, time 28,
  # altitude 44, geoid 52, HDOP 60, fix quality 62, motor 64, rudder 66, STW 68, wind 72 76 80 84,
  # air temperature 88, pressure 92.
  for spec in 0:0169 4:055D4A81 12:F5456AFF 24:0169 28:8000000000000000 62:09 64:80 66:65 \
    76:0169 84:FFFE; do
    bad+=("$(frame "$(set_field "$seed" "${spec%%:*}" "${spec#*:}")")")
  done
  {
    crlf "$(seal PYDIR,1,2)"
    for h in "${bad[@]}"; do hex2bin "$h"; done
    crlf "$(seal PYDIR,3,4)"
  } >"$work/in"
  expect_rc "frames outside the spec's ranges" 1 "$decode" <"$work/in"
  expect_eq "each is rejected, naming its field, and the sentences around them decode" \
    "$(printf '%s\n' PYDIR 2:out_of_range:1 2:out_of_range:2 2:out_of_range:3 2:out_of_range:5 \
      2:value_too_large:6 2:out_of_range:10 2:out_of_range:11 2:out_of_range:12 2:out_of_range:15 \
      2:out_of_range:17 PYDIR)" \
    "$(sed -e 's/^{"line":\([0-9]*\),"error":"\([a-z_]*\)","field":\([0-9]*\),.*/\1:\2:\3/' \
      -e 's/^{"type":"PYDIR".*/PYDIR/' "$work/out")"
  expect_eq "an out-of-range frame in full" \
    "{\"line\":2,\"error\":\"out_of_range\",\"field\":2,\"detail\":\"AB00 field 2 (latitude) 90.000001: value outside the range the spec allows\",\"input\":\"${bad[1]}\"}" \
    "$(line 3 "$work/out")"
  expect_eq "motor -128, as the decoder reads it" \
    '"detail":"AB00 field 11 (motor_pct) -128: value outside the range the spec allows",' \
    "$(grep -o '"detail":"AB00 field 11[^"]*",' "$work/out")"
  expect_rc "--format nmea drops them" 1 "$decode" --format nmea <"$work/in"
  expect_eq "only the sentences are written" "$(crlf "$(seal PYDIR,1,2)" "$(seal PYDIR,3,4)")" \
    "$(cat "$work/out")"
  expect_eq "one reason per frame on stderr" 10 "$(wc -l <"$work/err")"
  # The edges of every range, and "not available" (the spec's 0xFFFF air temperature too), decode
  # and come back from seawire-encode bit for bit (0xFFFF as the spec's 0x7FFF). Fields are
  # separated by '_' for reading.
  local na=FFFF_7FFFFFFF_7FFFFFFF_FFFF_FFFF
  good=(
    0168_055D4A80_F5456B00_FFFE_0000_7FFFFFFFFFFFFFFF_80000000_7FFFFFFE_FE_08_9C_64_0000_FFFE_0168_0000_0000_8000_FFFE
    0000_FAA2B580_0ABA9500_0000_0168_0000000000000000_7FFFFFFE_80000000_00_00_64_9C_FFFE_0000_0000_FFFE_0168_7FFE_0000
    "${na}_0000E677D21FDBFF_7FFFFFFF_7FFFFFFF_FF_FF_7F_7F_FFFF_FFFF_FFFF_FFFF_FFFF_FFFF_FFFF"
    "${na}_0000E677D21FDC00_7FFFFFFF_7FFFFFFF_FF_FF_7F_7F_FFFF_FFFF_FFFF_FFFF_FFFF_7FFF_FFFF"
  )
  good=("${good[@]//_/}")
  : >"$work/in"
  for h in "${good[@]}"; do hex2bin "$(frame "$h")" >>"$work/in"; done
  expect_rc "frames at the edges of the ranges" 0 "$decode" <"$work/in"
  cp "$work/out" "$work/edges.json"
  expect_eq "four frames" 4 "$(grep -c '^{"type":"AB00",' "$work/edges.json")"
  expect_eq "the edges, as decoded" \
    '"heading_deg":360,"latitude":90.000000,"longitude":-180.000000,"sog_mps":6553.4,"cog_deg":0,"gps_time":9223372036854775807,"alt_msl_m":-214748364.8,"geoid_sep_m":214748364.6,"hdop":25.4,"fix_quality":8,"motor_pct":-100,"rudder_pct":100,' \
    "$(line 1 "$work/edges.json" | grep -o '"heading_deg".*"rudder_pct":[^,]*,')"
  expect_eq "the last ISO time, and the first in milliseconds" \
    '"gps_time":"9999-12-31T23:59:59.999Z" "gps_time":253402300800000' \
    "$(line 3 "$work/edges.json" | grep -o '"gps_time":[^,]*') $(line 4 "$work/edges.json" | grep -o '"gps_time":[^,]*')"
  expect_rc "encode the edges" 0 "$encode" <"$work/edges.json"
  good[2]=${good[2]:0:88}7FFF${good[2]:92}
  if ! cmp -s "$work/out" <(for h in "${good[@]}"; do hex2bin "$(frame "$h")"; done); then
    fail "decode | encode changes a frame at the edges"
  fi
  # The sample log: every frame that decodes is sent back, and decodes to the same JSON.
  "$decode" <"$data/anello_mixed.nmea" >"$work/mixed.json"
  grep '^{"type":"AB00",' "$work/mixed.json" >"$work/frames.json"
  expect_rc "encode the sample log's frames" 0 "$encode" <"$work/frames.json"
  expect_eq "43 frames of 56 bytes" $((43 * 56)) "$(wc -c <"$work/out")"
  cp "$work/out" "$work/frames.bin"
  expect_rc "decode them again" 0 "$decode" <"$work/frames.bin"
  expect_eq "decode | encode | decode reproduces the frames" "$(cat "$work/frames.json")" \
    "$(cat "$work/out")"
}

# Numbers in exponent form (jq 1.6 prints 0.00001 as 1e-05) are written out, digit for digit.
case_exponents() {
  cat >"$work/in" <<'JSON'
{"type":"PYDIR","thrust_left":1e-05,"thrust_right":-2.50E+1}
{"type":"PYDIR","thrust_left":1.5e1,"thrust_right":1e0}
{"type":"PYDIR","thrust_left":1.50e-1,"thrust_right":0.5E1}
{"type":"PYDIR","thrust_left":123e-1,"thrust_right":-1.23e+1}
{"type":"CPNVG","timestamp":"08:10:25.987","latitude":-0.0e1,"longitude":-7125e-2,"position_quality":true}
{"type":"CPNVG","timestamp":"08:10:25.987","latitude":4.25E+1,"longitude":-71.25,"position_quality":true,"precision":{"latitude":2e0}}
{"type":"PYDIR","thrust_left":-2.50E+2,"thrust_right":1}
{"type":"PYDIR","thrust_left":1e41,"thrust_right":1}
{"type":"PYDIR","thrust_left":1,"thrust_right":1E-41}
{"type":"PYDIR","thrust_left":1234567890123456789012345678901234567890123456789e-1,"thrust_right":1}
{"type":"CPNVG","timestamp":"08:10:25.987","latitude":42.5,"longitude":-71.25,"position_quality":true,"precision":{"latitude":2e99}}
{"type":"PYDIR","thrust_left":1e-0000000000000000000000000000000000000005,"thrust_right":1}
JSON
  expect_rc "encode numbers with exponents" 1 "$encode" <"$work/in"
  expect_eq "sent with the mantissa's digits, the point moved" "$(crlf "$(seal PYDIR,0.00001,-25.0)" \
    "$(seal PYDIR,15,1)" "$(seal PYDIR,0.150,5)" "$(seal PYDIR,12.3,-12.3)" \
    "$(seal CPNVG,081025.987,0000.0000,S,07115.0000,W,1,,,,,,)" \
    "$(seal CPNVG,081025.987,4230.00,N,07115.0000,W,1,,,,,,)" "$(seal PYDIR,0.00001,1)")" \
    "$(cat "$work/out")"
  expect_eq "absurd exponents are refused, naming line and field" "$(printf '%s\n' \
    'seawire-encode: line 7: PYDIR field 1 (thrust_left) -250: out_of_range: value outside the range the spec allows' \
    'seawire-encode: line 8: field "thrust_left" 1e41: an exponent beyond +-40 is not written out (write the number without an exponent)' \
    'seawire-encode: line 9: field "thrust_right" 1E-41: an exponent beyond +-40 is not written out (write the number without an exponent)' \
    'seawire-encode: line 10: field "thrust_left" 1234567890123456789012345678901234567890123456789e-1: more than 48 digits written out (write the number without an exponent)' \
    'seawire-encode: line 11: "precision" of "latitude" 2e99: an exponent beyond +-40 is not written out (write the number without an exponent)')" \
    "$(cat "$work/err")"
  # seawire-decode | jq | seawire-encode, with jq 1.6's number printing: the same bytes.
  "$decode" <"$data/anello_mixed.nmea" >"$work/mixed.json"
  sed -e 's/"longitude":-0\.000013,/"longitude":-1.3e-05,/' \
    -e 's/"wind_speed_abs_mps":0\.2,/"wind_speed_abs_mps":2e-1,/' "$work/mixed.json" >"$work/jq.json"
  expect_eq "lines with exponents" 2 \
    "$(grep -c -e '"longitude":-1.3e-05,' -e '"wind_speed_abs_mps":2e-1,' "$work/jq.json")"
  "$encode" <"$work/mixed.json" >"$work/plain.out"
  expect_rc "encode the log as jq 1.6 prints it" 0 "$encode" <"$work/jq.json"
  if ! cmp -s "$work/out" "$work/plain.out"; then
    fail "exponent forms are not sent as the plain numbers"
  fi
}

# "precision" is checked like the message's keys: position fields only, whole numbers in range.
case_precision() {
  local nvg='{"type":"CPNVG","timestamp":"08:10:25.987","latitude":42.5,"longitude":-71.25,"position_quality":true'
  local hrb='{"type":"RXHRB","date":"2018-12-10","time":"16:12:29","latitude":21.31198,"longitude":-157.88972,"team_id":"AUVSI","system_mode":"2","auv_status":"1"'
  printf '%s\n' "$nvg"',"precision":{"latitud":2}}' "$nvg"',"precision":5}' \
    "$nvg"',"precision":[2]}' "$nvg"',"precision":{"latitude":13}}' \
    "$nvg"',"precision":{"latitude":0}}' "$nvg"',"precision":{"latitude":2.5}}' \
    "$nvg"',"precision":{"latitude":-1}}' \
    '{"type":"PYDIR","thrust_left":1,"thrust_right":2,"precision":{"foo":3}}' \
    "$hrb"',"precision":{"latitude":19}}' "$hrb"',"precision":{"latitude":0,"longitude":7}}' \
    "$nvg"',"precision":{"latitude":12,"longitude":"1"}}' "$nvg"',"precision":{"latitude":null}}' \
    '{"type":"XXABC","fields":["1"],"foo":2}' >"$work/in"
  expect_rc "encode with precision objects" 1 "$encode" <"$work/in"
  expect_eq "in-range precisions are used" "$(crlf \
    "$(seal RXHRB,101218,161229,21,N,157.8897200,W,AUVSI,2,1)" \
    "$(seal CPNVG,081025.987,4230.000000000000,N,07115.0,W,1,,,,,,)" \
    "$(seal CPNVG,081025.987,4230.0000,N,07115.0000,W,1,,,,,,)")" "$(cat "$work/out")"
  expect_eq "unknown precision keys and bad values are refused, naming line and key" "$(printf '%s\n' \
    'seawire-encode: line 1: CPNVG: unknown key "latitud" in "precision" (allowed: the position fields latitude, longitude)' \
    'seawire-encode: line 2: CPNVG: "precision" must be an object giving position fields their fraction digits (e.g. "precision":{"latitude":5})' \
    'seawire-encode: line 3: CPNVG: "precision" must be an object giving position fields their fraction digits (e.g. "precision":{"latitude":5})' \
    'seawire-encode: line 4: CPNVG: "precision" of "latitude" is 13: must be a whole number from 1 to 12 (minute places of a DDMM.mmm position)' \
    'seawire-encode: line 5: CPNVG: "precision" of "latitude" is 0: must be a whole number from 1 to 12 (minute places of a DDMM.mmm position)' \
    'seawire-encode: line 6: CPNVG: "precision" of "latitude" is 2.5: must be a whole number from 1 to 12 (minute places of a DDMM.mmm position)' \
    'seawire-encode: line 7: CPNVG: "precision" of "latitude" is -1: must be a whole number from 1 to 12 (minute places of a DDMM.mmm position)' \
    'seawire-encode: line 8: PYDIR: unknown key "foo" in "precision" (PYDIR has no position fields)' \
    'seawire-encode: line 9: RXHRB: "precision" of "latitude" is 19: must be a whole number from 0 to 18 (degree places of a decimal-degree position)' \
    'seawire-encode: line 13: XXABC: unknown key "foo" (a sentence no message describes takes only "type", "fields" and "start")')" \
    "$(cat "$work/err")"
}

case_usage() {
  expect_rc "decode --format xml" 2 "$decode" --format xml </dev/null
  expect_rc "decode --no-such-option" 2 "$decode" --no-such-option </dev/null
  expect_rc "decode --checksum sometimes" 2 "$decode" --checksum sometimes </dev/null
  expect_rc "decode extra argument" 2 "$decode" file.nmea </dev/null
  expect_rc "encode --no-such-option" 2 "$encode" --no-such-option </dev/null
  expect_rc "decode --help" 0 "$decode" --help
  for want in --format --checksum --strict --stats --line-buffered --help 'Examples:' \
    'seawire-decode --format none --stats' 'Exit status'; do
    if ! grep -q -- "$want" "$work/out"; then fail "decode --help does not mention $want"; fi
  done
  expect_rc "encode --help" 0 "$encode" --help
  for want in --line-buffered --help 'Examples:' precision AB00 'Exit status'; do
    if ! grep -q -- "$want" "$work/out"; then fail "encode --help does not mention $want"; fi
  done
  expect_rc "decode, empty input" 0 "$decode" </dev/null
  expect_eq "empty input, empty output" "" "$(cat "$work/out" "$work/err")"
}

case_encode() {
  cat >"$work/in" <<'EOF'
{"type":"PYDIR","thrust_left":1.50,"thrust_right":-20}
not json
{"thrust_left":1}
{"type":"PYDIR","thrust_left":120,"thrust_right":0}
{"type":"PYDEV","heading_deg":90,"speed_mps":1.5,"speeed":2}

{"type":"CPNVG","timestamp":"08:10:25.987","latitude":42.36351533,"longitude":-71.1140838,"position_quality":true,"heading_deg":203.1,"nav_timestamp":"08:10:25.980"}
{"type":"CPNVG","timestamp":"08:10:25.987","latitude":"north","longitude":-71.1,"position_quality":true}
{"type":"CPNVG","timestamp":"08:10:25.987","latitude":42.5,"longitude":-71.25,"position_quality":1,"precision":{"latitude":2,"longitude":6}}
{"type":"GNRMC","status":"V","date":"2019-05-01"}
{"type":"XXABC","fields":["1","","two words"]}
{"type":"XXABC"}
{"type":"XXABC","fields":["a,b"]}
{"type":"RXHRB","date":"2018-12-10","time":"16:12:29","latitude":21.31198,"longitude":-157.88972,"team_id":"AUVSI","system_mode":"2","auv_status":"1"}
{"type":"RXHRB","date":"2018-12-10","time":"16:12:29.5","team_id":"AUVSI","system_mode":"2"}
{"type":"BPSTS","timestamp":"23:11:33.12","all_ok":true,"message":"all good, really"}
{"line":3,"error":"bad_enum","field":1,"detail":"","input":""}
EOF
  expect_rc "encode with errors" 1 "$encode" <"$work/in"
  expect_eq "good lines are sent, digits as written" "$(crlf "$(seal PYDIR,1.50,-20)" \
    "$(seal CPNVG,081025.987,4221.810920,N,07106.84503,W,1,,,203.1,,,081025.980)" \
    "$(seal CPNVG,081025.987,4230.00,N,07115.000000,W,1,,,,,,)" "$(seal GNRMC,,V,,,,,,,010519,,)" \
    "$(seal 'XXABC,1,,two words')" '$RXHRB,101218,161229,21.31198,N,157.88972,W,AUVSI,2,1*06')" \
    "$(cat "$work/out")"
  expect_eq "each rejected line named, with its field and reason" "$(printf '%s\n' \
    'seawire-encode: line 2: invalid JSON: [json.exception.parse_error.101] parse error at line 1, column 2: syntax error while parsing value - invalid literal; last read: '"'"'no'"'"'' \
    'seawire-encode: line 3: no "type" string' \
    'seawire-encode: line 4: PYDIR field 1 (thrust_left) 120: out_of_range: value outside the range the spec allows' \
    'seawire-encode: line 5: PYDEV: unknown key "speeed" (not a field of PYDEV)' \
    'seawire-encode: line 8: CPNVG field 2 (latitude) "north": bad_latitude: latitude malformed or beyond 90 degrees' \
    'seawire-encode: line 12: unknown_address: no known message is "XXABC" (and there is no "fields" array to send it as is)' \
    'seawire-encode: line 13: XXABC field 1 (fields): bad_text: text contains a character the field may not carry' \
    'seawire-encode: line 15: RXHRB field 2 (time) "16:12:29.5": bad_time: time is not hhmmss[.fff]' \
    'seawire-encode: line 16: BPSTS field 3 (message) "all good, really": bad_text: text contains a character the field may not carry')" \
    "$(cat "$work/err")"
  # A NUL or a control byte in a JSON string is named escaped, and the reason is not cut there.
  printf '%s\n' '{"type":"BPSTS","timestamp":"23:11:33.12","all_ok":false,"message":"a\u0000b\u0001"}' >"$work/in"
  expect_rc "encode: NUL in text" 1 "$encode" <"$work/in"
  expect_eq "control bytes escaped in the reason" \
    'seawire-encode: line 1: BPSTS field 3 (message) "a\x00b\x01": bad_text: text contains a character the field may not carry' \
    "$(cat "$work/err")"
}

# An AIS receiver's lines mixed into a log: each '!' sentence (NMEA 0183 encapsulation) is a
# well-formed unknown sentence with "start":"!", --format nmea writes it back as it came, and
# seawire-encode sends its JSON as the same line. A '!' inside a '$' sentence's text is text.
case_ais() {
  local vdm='!AIVDM,1,1,,B,15M67FC000G?ufbE`vJ8?wv4R0<4,0*10'
  local vdo='!AIVDO,1,1,,,B5NJ;PP005l4ot5Isbl03wsUkP06,0*35'
  crlf "$(seal PAPGPSCTRL,1)" "$vdm" "$(seal VMVBW,0.0,0.0,A,0.0,0.0,A)" "$vdo" >"$work/log"
  expect_rc "decode a log with AIS lines" 0 "$decode" <"$work/log"
  expect_eq "no error" "" "$(cat "$work/err")"
  expect_eq "one JSON object per line" 4 "$(wc -l <"$work/out")"
  expect_eq "!AIVDM: an unknown sentence, its start said" \
    '{"type":"AIVDM","start":"!","fields":["1","1","","B","15M67FC000G?ufbE`vJ8?wv4R0<4","0"]}' \
    "$(line 2 "$work/out")"
  expect_eq "!AIVDO too" \
    '{"type":"AIVDO","start":"!","fields":["1","1","","","B5NJ;PP005l4ot5Isbl03wsUkP06","0"]}' \
    "$(line 4 "$work/out")"
  expect_eq "the '$' sentences around them" '{"type":"PAPGPSCTRL","control":"1"}' \
    "$(line 1 "$work/out")"
  cp "$work/out" "$work/log.json"
  expect_rc "decode --format nmea" 0 "$decode" --format nmea <"$work/log"
  if ! cmp -s "$work/out" "$work/log"; then fail "the log with AIS lines not written back as it came"; fi
  expect_rc "encode the JSON" 0 "$encode" <"$work/log.json"
  if ! cmp -s "$work/out" "$work/log"; then fail "seawire-encode did not send the AIS lines back"; fi
  # "start" is "$" or "!"; with "!" a known address is still no message.
  printf '%s\n' '{"type":"XXABC","start":"$","fields":["1"]}' \
    '{"type":"GPRMC","start":"!","fields":["x"]}' '{"type":"XXABC","start":"?","fields":[]}' \
    '{"type":"XXABC","start":"!"}' >"$work/in"
  expect_rc "encode with start keys" 1 "$encode" <"$work/in"
  expect_eq "start keys sent" "$(crlf "$(seal XXABC,1)" '!GPRMC,x*1F')" "$(cat "$work/out")"
  expect_eq "bad start keys refused" "$(printf '%s\n' \
    'seawire-encode: line 3: XXABC: "start" must be "$" or "!"' \
    'seawire-encode: line 4: unknown_address: no known message is "XXABC" (and there is no "fields" array to send it as is)')" \
    "$(cat "$work/err")"
  # A status text that ends with '!' is not cut: the sentence is whole.
  crlf "$(seal 'BPSTS,231133.12,1,Mission done!')" >"$work/in"
  expect_rc "decode a '!' in text" 0 "$decode" <"$work/in"
  expect_eq "the text keeps its '!'" \
    '{"type":"BPSTS","timestamp":"23:11:33.12","all_ok":true,"message":"Mission done!"}' \
    "$(cat "$work/out")"
}

# What receivers in the field send: a blank GGA fix quality, an RMC variation no variation can
# have, a '*' with no digits, a line cut off without a checksum; positions printed within 5e-10
# degrees and read back to the same minutes.
case_receivers() {
  local gga rmc999 rmcletter cut star
  gga=$(seal 'GPGGA,105027.80,5612.9956,N,00306.6983,W,,03,2.506,160.002,M,,M,,')
  rmc999=$(seal 'GPRMC,001053.00,A,4404.14083,N,12118.85886,W,0.011,,220218,999.9,E,A')
  rmcletter=$(seal 'GPRMC,001053.00,A,4404.14083,N,12118.85886,W,0.011,,220218,,E,A')
  cut='$GNRMC,001053.00,A,4404.14083,N,12118.85886,W,0.'
  star='$GPGGA,105027.80,5612.9956,N,00306.6983,W,1,03,2.506,160.002,M,,M,,*'
  crlf "$gga" "$rmc999" "$rmcletter" "$star" "$cut" >"$work/log"
  expect_rc "decode what receivers send" 1 "$decode" <"$work/log"
  expect_eq "three fixes kept, two corrupt lines refused" 5 "$(wc -l <"$work/out")"
  expect_eq "blank fix quality: null, the fix kept" \
    '{"type":"GPGGA","time":"10:50:27.80","latitude":56.216593333333,"longitude":-3.111638333333,"quality":null,"satellites":3,"hdop":2.506,"altitude_m":160.002,"geoid_separation_m":null,"dgps_age_s":null,"dgps_station":null}' \
    "$(line 1 "$work/out")"
  expect_eq "999.9,E: no variation, the fix kept" \
    '{"type":"GPRMC","time":"00:10:53.00","status":"A","latitude":44.0690138333333,"longitude":-121.3143143333333,"speed_knots":0.011,"course_true":null,"date":"2018-02-22","magnetic_variation":null,"mode":"A","navigational_status":null}' \
    "$(line 2 "$work/out")"
  expect_eq "'*' then the line end: a checksum cut off" \
    '"error":"bad_checksum_format"' "$(line 4 "$work/out" | grep -o '"error":"[a-z_]*"')"
  expect_eq "cut off without a checksum: too_few_fields at course_true" \
    '"error":"too_few_fields","field":8' "$(line 5 "$work/out" | grep -o '"error":"[a-z_]*","field":[0-9]*')"
  # Written back: the variation's letter stays; the impossible value goes.
  expect_rc "--format nmea" 1 "$decode" --format nmea <"$work/log"
  expect_eq "written back" "$(crlf "$gga" "$rmcletter" "$rmcletter")" "$(cat "$work/out")"
  # JSON | encode gives the same minutes back, digit for digit, trailing zeros too.
  crlf "$(seal 'GPGGA,105027.80,5612.99,N,01200.76,E,1,03,2.5,160.0,M,,M,,')" \
    "$(seal 'GPGGA,105027.80,5612.9900,N,01200.7600,E,1,03,2.5,160.0,M,,M,,')" \
    "$(seal 'GPGGA,105027.80,5612.990000,N,01200.760000,E,1,03,2.5,160.0,M,,M,,')" >"$work/pos"
  expect_rc "decode positions" 0 "$decode" <"$work/pos"
  expect_eq "0.76' / 60 printed to 1e-10 degrees" '"longitude":12.0126666667' \
    "$(line 1 "$work/out" | grep -o '"longitude":[0-9.]*')"
  cp "$work/out" "$work/pos.json"
  expect_rc "encode positions" 0 "$encode" <"$work/pos.json"
  if ! cmp -s "$work/out" "$work/pos"; then
    fail "positions not written back digit for digit"
    diff "$work/pos" "$work/out" >&2 || true
  fi
}

# A live link whose sender ends lines with CR alone: under --line-buffered each sentence comes
# out while the input is still open (once the input has been quiet), not when the next one
# arrives; an LF that comes later completes that CR and is no blank line.
# Each sentence is read by the rules of the role that receives it; the vehicle's own number
# forms (unpadded positions under one degree, nan, -0) are read and kept.
case_roles() {
  # A payload's command without a checksum ends in a bare '*' (MOOS iM200, Clearpath's tester).
  printf '%s\r\n' '$PYDIR,45.00000,-30.00000*' '$PYDIR,1.000000,-1.000000*' '$PYCLT,0*' \
    '$PYDIR,45,55' >"$work/in"
  local want
  want=$(printf '%s\n' '{"type":"PYDIR","thrust_left":45.00000,"thrust_right":-30.00000}' \
    '{"type":"PYDIR","thrust_left":1.000000,"thrust_right":-1.000000}' \
    '{"type":"PYCLT","lights_on":false}' '{"type":"PYDIR","thrust_left":45,"thrust_right":55}')
  expect_rc "commands ending in a bare '*', default" 0 "$decode" <"$work/in"
  expect_eq "read as the vehicle reads them" "$want" "$(cat "$work/out")"
  expect_rc "commands ending in a bare '*', --checksum verify" 0 "$decode" -c verify <"$work/in"
  expect_eq "--checksum verify keeps the role's bare '*'" "$want" "$(cat "$work/out")"
  expect_rc "commands ending in a bare '*', --checksum ignore" 0 "$decode" -c ignore <"$work/in"
  expect_eq "--checksum ignore keeps the role's bare '*'" "$want" "$(cat "$work/out")"
  expect_rc "commands ending in a bare '*', --checksum required" 1 "$decode" -c required \
    --format none <"$work/in"
  expect_eq "--checksum required: none of them has one" \
    "$(printf '%s\n' 'line 1: missing_checksum' 'line 2: missing_checksum' 'line 3: missing_checksum' \
      'line 4: missing_checksum')" "$(sed 's/^seawire-decode: \(line [0-9]*: [a-z_]*\):.*/\1/' "$work/err")"
  expect_rc "commands ending in a bare '*', --strict" 1 "$decode" --strict --format none <"$work/in"
  expect_eq "--strict: seawire never writes a bare '*'" \
    "$(printf '%s\n' 'line 1: bad_checksum_format' 'line 2: bad_checksum_format' \
      'line 3: bad_checksum_format' 'line 4: missing_checksum')" \
    "$(sed 's/^seawire-decode: \(line [0-9]*: [a-z_]*\):.*/\1/' "$work/err")"
  # What a vehicle sends always has a checksum: a payload refuses it without one. What a payload
  # sends a Sandshark may leave it out.
  printf '%s\r\n' '$CPALT,164959.100,1' '$CPALT,164959.100,1*' '$BPLOG,ALL,ON' '$RXHRB,111221,161229,21.31198,N,157.88972,W,ROBOT,2,1' \
    '$PAPGPSCTRL,1' '$GPRMC,164959.00,A,4221.71114,N,07105.44878,W,0.145,156.78,311214,,,A' >"$work/in"
  expect_rc "checksums by role" 1 "$decode" <"$work/in"
  expect_eq "required from the vehicle, the RobotX judge's and the INS's senders" \
    "$(printf '%s\n' '1:missing_checksum' '2:bad_checksum_format' '{"type":"BPLOG","code":"ALL","state":"ON"}' \
      '4:missing_checksum' '5:missing_checksum' \
      '{"type":"GPRMC","time":"16:49:59.00","status":"A","latitude":42.3618523333333,"longitude":-71.0908130,"speed_knots":0.145,"course_true":156.78,"date":"2014-12-31","magnetic_variation":null,"mode":"A","navigational_status":null}')" \
    "$(sed 's/^{"line":\([0-9]*\),"error":"\([a-z_]*\)".*/\1:\2/' "$work/out")"
  expect_rc "checksums by role, --checksum verify" 1 "$decode" -c verify --format none <"$work/in"
  expect_eq "--checksum verify for every role; a bare '*' is no checksum only in a command" \
    'line 2: bad_checksum_format' "$(sed 's/^seawire-decode: \(line [0-9]*: [a-z_]*\):.*/\1/' "$work/err")"

  # The Clearpath vehicle's unpadded positions within one degree of 0,0.
  crlf "$(seal CPNVG,164959.034,4221.711138,N,22.2,W,1,0,0,234.3,-6.8,-1.7,)" \
    "$(seal CPNVG,164959.034,44.598,S,7105.44878,W,1,0,0,234.3,-6.8,-1.7,)" \
    "$(seal CPNVG,164959.034,0.0,S,0.0,W,1,,,0,,,164959.000)" \
    "$(seal GPRMC,164959.00,A,37.352387,N,07105.44878,W,0.145,156.78,311214,,,A)" >"$work/in"
  expect_rc "unpadded positions" 1 "$decode" <"$work/in"
  expect_eq "minutes of zero degrees in CPNVG; decimal degrees refused in GPRMC" \
    "$(printf '%s\n' '42.36185230,-0.370' '-0.74330,-71.0908130' '-0.000,-0.000' \
      'bad_latitude:3')" \
    "$(sed -e 's/.*"latitude":\([-0-9.]*\),"longitude":\([-0-9.]*\),.*/\1,\2/' \
      -e 's/^{"line":4,"error":"\([a-z_]*\)","field":\([0-9]*\).*/\1:\2/' "$work/out")"
  head -n 3 "$work/in" >"$work/vehicle"
  expect_rc "unpadded positions, --format nmea" 0 "$decode" --format nmea <"$work/vehicle"
  expect_eq "written back as they came" "$(cat "$work/vehicle")" "$(cat "$work/out")"
  expect_rc "unpadded positions, --strict" 0 "$decode" --strict --format none <"$work/vehicle"

  # nan from the vehicle: not available, the rest of the sentence kept; -0 keeps its sign.
  crlf "$(seal CPNVR,164959.063,nan,-NaN,0,0.060938,-0,-0.061132)" >"$work/in"
  expect_rc "nan velocities" 0 "$decode" <"$work/in"
  want='{"type":"CPNVR","timestamp":"16:49:59.063","vel_east_mps":null,"vel_north_mps":null,"vel_down_mps":0,"pitch_rate_dps":0.060938,"roll_rate_dps":-0,"yaw_rate_dps":-0.061132}'
  expect_eq "nan is null, yaw rate kept, -0 keeps its sign" "$want" "$(cat "$work/out")"
  expect_rc "nan velocities, --format nmea" 0 "$decode" --format nmea <"$work/in"
  expect_eq "nan is never written" "$(crlf "$(seal CPNVR,164959.063,,,0,0.060938,-0,-0.061132)")" \
    "$(cat "$work/out")"
  expect_rc "nan velocities, --strict" 1 "$decode" --strict --format none <"$work/in"
  printf '%s\n' "$want" '{"type":"PYDIR","thrust_left":-0,"thrust_right":0}' >"$work/in"
  expect_rc "-0 through seawire-encode" 0 "$encode" <"$work/in"
  expect_eq "the sign of zero is written" \
    "$(crlf "$(seal CPNVR,164959.063,,,0,0.060938,-0,-0.061132)" "$(seal PYDIR,-0,0)")" \
    "$(cat "$work/out")"
  "$encode" <"$work/in" | "$decode" >"$work/again"
  expect_eq "decode | encode | decode keeps -0" \
    "$(printf '%s\n' "$want" '{"type":"PYDIR","thrust_left":-0,"thrust_right":0}')" "$(cat "$work/again")"

  # The vehicle's seconds printed "%06.3f": 16:49:59.9995 and later is "164960.000".
  crlf "$(seal CPNVG,164960.000,4221.711142,N,07105.44878,W,1,0,0,234.32964,-6.796959,-1.706798,164959.006)" \
    "$(seal GPRMC,164960.00,A,4221.71114,N,07105.44878,W,0.145,156.78,311214,,,A)" >"$work/in"
  expect_rc "seconds rounded up to 60" 1 "$decode" <"$work/in"
  expect_eq "kept in CPNVG, refused in GPRMC" \
    "$(printf '%s\n' '"16:49:60.000"' 'second_out_of_range:1')" \
    "$(sed -e 's/^{"type":"CPNVG","timestamp":\("[^"]*"\).*/\1/' \
      -e 's/^{"line":2,"error":"\([a-z_]*\)","field":\([0-9]*\).*/\1:\2/' "$work/out")"
  head -n 1 "$work/out" >"$work/json"
  expect_rc "seconds rounded up to 60, through seawire-encode" 0 "$encode" <"$work/json"
  expect_eq "written back as it came" "$(head -n 1 "$work/in")" "$(cat "$work/out")"
}

case_live() {
  local fifo=$work/fifo first second
  first=$(seal 'PAPGPSCTRL,1')
  second=$(seal 'PAPGPSCTRL,0')
  mkfifo "$fifo"
  "$decode" --line-buffered <"$fifo" >"$work/out" 2>"$work/err" &
  local pid=$! rc=0 i
  exec 3>"$fifo"
  printf '%s\r' "$first" >&3
  for ((i = 0; i < 100; i++)); do
    [[ -s $work/out ]] && break
    sleep 0.1
  done
  expect_eq "a CR-ended sentence comes out while the input stays open" \
    '{"type":"PAPGPSCTRL","control":"1"}' "$(cat "$work/out")"
  printf '\n%s\r' "$second" >&3
  for ((i = 0; i < 100; i++)); do
    [[ $(wc -l <"$work/out") -ge 2 ]] && break
    sleep 0.1
  done
  expect_eq "and the next one too" 2 "$(wc -l <"$work/out")"
  printf '$PAPGPSCTRL,7*11\r' >&3
  exec 3>&-
  wait "$pid" || rc=$?
  expect_eq "exit status: the last sentence rejected" 1 "$rc"
  expect_eq "the late LF was no blank line: the rejected sentence is on line 3" \
    '{"line":3,"error":"checksum_mismatch","field":0,"detail":"checksum does not match the sentence (sent 11, computed 17) at column 14","input":"$PAPGPSCTRL,7*11"}' \
    "$(line 3 "$work/out")"
}

case_reasons() {
  # An enum value in the other message's spelling is accepted and given in the message's own
  # (tools/decode/README.md, docs/round-trip.md): RobotX's cruciform.
  crlf "$(seal RXDOK,101218,161229,AUVSI,G,CRUCI)" "$(seal RXDEL,101218,161229,AUVSI,G,CRUC)" \
    >"$work/in"
  expect_rc "both cruciform spellings" 0 "$decode" <"$work/in"
  expect_eq "JSON: each message's own spelling" '"shape":"CRUC" "shape":"CRUCI"' \
    "$(grep -o '"shape":"[A-Z]*"' "$work/out" | tr '\n' ' ' | sed 's/ $//')"
  expect_rc "both cruciform spellings, nmea" 0 "$decode" --format nmea <"$work/in"
  expect_eq "nmea: each message's own spelling" \
    "$(crlf "$(seal RXDOK,101218,161229,AUVSI,G,CRUC)" "$(seal RXDEL,101218,161229,AUVSI,G,CRUCI)")" \
    "$(cat "$work/out")"

  # Each rejected line says which field, named for what it is, and what is wrong with its text.
  crlf "$(seal RXHRB,101218,161229,29.6412654321,,-82.3456789012,,GATOR,1,1)" \
    "$(seal RXHRB,101218,161229,29.6412654321,N,-82.3456789012,W,GATOR,1,1)" \
    "$(seal GPRMC,134213.686,A,00.00,N,000.00,W,0,0,291263,0,E)" \
    "$(seal GPRMC,134213.686,A,-4221.7,N,07105.4,W,0,0,291263,0,E)" \
    "$(seal GPRMC,134213.686,A,37.352387,N,07105.4,W,0,0,291263,0,E)" \
    "$(seal CPNVG,101218,4221.7,,07105.4,W,1,1,0,0,0,0,0,0,0)" \
    '$GPRMC,134213.686,A,0000.00,N,00000.00,W,0,0,291263,0,E*0a' \
    '$RXHRB,101218,161229,29.6412654321,N,82.3456789012,W,GATOR,1,1*42' \
    "$(seal BPLOG,ACKS,ON)" "$(seal BPLOG,AC,ON)" >"$work/in"
  expect_rc "refused fields" 1 "$decode" --format none <"$work/in"
  expect_eq "the reasons" "$(
    printf '%s\n' \
      'seawire-decode: line 1: bad_hemisphere: RXHRB field 4 (latitude'"'"'s hemisphere letter) "": hemisphere letter is missing (blank)' \
      'seawire-decode: line 2: bad_longitude: RXHRB field 5 (longitude) "-82.3456789012": a sign is not allowed: the hemisphere letter carries it' \
      'seawire-decode: line 3: bad_latitude: GPRMC field 3 (latitude) "00.00": DDMM.m needs two minute digits and at least one degree digit before the point' \
      'seawire-decode: line 4: bad_latitude: GPRMC field 3 (latitude) "-4221.7": a sign is not allowed: the hemisphere letter carries it' \
      'seawire-decode: line 5: bad_latitude: GPRMC field 3 (latitude) "37.352387": DDMM.m needs two minute digits and at least one degree digit before the point' \
      'seawire-decode: line 6: bad_hemisphere: CPNVG field 3 (latitude'"'"'s hemisphere letter) "": hemisphere letter is missing (blank)' \
      'seawire-decode: line 7: checksum_mismatch: checksum does not match the sentence (sent 0a, computed 67) at column 56' \
      'seawire-decode: line 8: checksum_mismatch: checksum does not match the sentence (sent 42, computed 2A: written in decimal?) at column 63' \
      'seawire-decode: line 9: bad_length: BPLOG field 1 (code) "ACKS": wrong length: exactly 3 characters' \
      'seawire-decode: line 10: bad_length: BPLOG field 1 (code) "AC": wrong length: exactly 3 characters'
  )" "$(grep '^seawire-decode: line' "$work/err")"
  # The JSON report carries the same words.
  expect_rc "refused fields, JSON" 1 "$decode" <"$work/in"
  expect_eq "JSON detail of the blank letter" \
    '{"line":1,"error":"bad_hemisphere","field":4,"detail":"RXHRB field 4 (latitude'"'"'s hemisphere letter) \"\": hemisphere letter is missing (blank)","input":"'"$(seal RXHRB,101218,161229,29.6412654321,,-82.3456789012,,GATOR,1,1)"'"}' \
    "$(line 1 "$work/out")"
}

"case_$case_name"
if ((failures > 0)); then
  echo "$case_name: $failures check(s) failed" >&2
  exit 1
fi
echo "$case_name: ok"
