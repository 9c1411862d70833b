#!/usr/bin/env bash
# SPDX-License-Identifier: BSL-1.0
# Runs the real seawire-decode and seawire-encode over examples/data and checks their output,
# errors and exit status. One ctest test per case (tests/programs/CMakeLists.txt):
#   programs_test.sh <seawire-decode> <seawire-encode> <examples/data> <case>
set -euo pipefail

decode=$1
encode=$2
data=$3
case_name=$4
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
    '{"type":"GPRMC","time":"16:49:59.00","status":"A","latitude":42.3618523,"longitude":-71.0908130,"speed_knots":0.145,"course_true":156.78,"date":"2014-12-31","magnetic_variation":null,"mode":"A","navigational_status":null}' \
    "$(line 2 "$k")"
  expect_eq "GPGGA relayed by the vehicle" \
    '{"type":"GPGGA","time":"16:49:59.00","latitude":42.3618523,"longitude":-71.0908130,"quality":"1","satellites":6,"hdop":2.80,"altitude_m":46.6,"geoid_separation_m":-33.2,"dgps_age_s":null,"dgps_station":null}' \
    "$(line 3 "$k")"
  expect_eq "CPNVG with unpadded longitude" \
    '{"type":"CPNVG","timestamp":"16:49:59.034","latitude":42.36185237,"longitude":-71.0908130,"position_quality":true,"altitude_m":0,"depth_m":0,"heading_deg":234.32964,"roll_deg":-6.796959,"pitch_deg":-1.706798,"nav_timestamp":"16:49:59.006"}' \
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
  # RobotX: the seed's five reports, decimal-degree positions signed.
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
    '9:out_of_range:1' '10:bad_character:0' '11:text_too_long:7' '12:truncated:0'
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
    '{"line":7,"error":"missing_start","field":0,"detail":"bytes outside any sentence or frame (no '"'"'$'"'"' before them); dropped","input":"### vehicle rebooted ###"}' \
    "$(line 7 "$o")"
  expect_eq "a control byte, escaped in the report" \
    '"input":"$CPNVR,164959.063,0.029\u000141,-0.068552,0,0.060938,0,-0.061132*59"}' \
    "$(line 10 "$o" | grep -o '"input".*')"
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
  # The sample logs hold every message type seawire knows, so the round trip covers them all.
  local type missing=()
  for type in CPNVG CPNVR CPRCM CPRBS CPIMU CPALT PYDEP PYDEV PYDIR PYCLT BFSHT BFVER BFNVG BFNVR \
    BFMIS BFACK BFCTL BPLOG BPSTS BPRMB BPABT BPVER RXHRB RXGAT RXCOD RXDOK RXDEL PAPGPSCTRL AB00 \
    ..RMC ..GGA ..RPM ..RSA ..VHW ..VBW ..VWR; do
    grep -q "^{\"type\":\"$type\"," "$work"/*.json || missing+=("$type")
  done
  expect_eq "every message type in the sample logs" "" "${missing[*]}"
  # Kingfisher: the only difference is the vehicle's unpadded longitude degrees.
  expect_eq "kingfisher: padded longitude is the only change" \
    "$(sed 's/,\([0-9]\{4\}\.[0-9]*\),W,/,0\1,W,/' "$data/kingfisher.nmea" | tr -d '\r' | cut -d'*' -f1)" \
    "$(tr -d '\r' <"$work/kingfisher.again" | cut -d'*' -f1)"
  # ANELLO: only the seed frame changes, whose air temperature 0xFFFF ("not available" in the
  # seed's own example) is sent as the spec's 0x7FFF: the frame's byte 52 and its CRC (4-7),
  # counted from 1 in the file (the frame follows an 18-byte sentence).
  expect_eq "anello_mixed: only the seed frame's air temperature and CRC differ" \
    "23 24 25 26 71" \
    "$(cmp -l "$work/anello_mixed.again" "$data/anello_mixed.nmea" | awk '{printf "%s ", $1}' |
      sed 's/ $//')"
  # Error objects from decode are passed over by encode.
  "$decode" <"$data/bad.nmea" >"$work/bad.json" || true
  expect_rc "encode decode's output of bad.nmea" 0 "$encode" <"$work/bad.json"
  expect_eq "only the good sentences come back" "$(crlf "$(line 1 "$data/bad.nmea" | tr -d '\r')" \
    '$PYDIR,45,55*57' "$(line 14 "$data/bad.nmea" | tr -d '\r')")" "$(cat "$work/out")"
}

case_options() {
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

# hex2bin <hex>: the bytes.
hex2bin() { printf "$(sed 's/../\\x&/g' <<<"$1")"; }
seed_frame=AB0000308EF7F176005901F4ECFFF903369A0000FFFF00000190794363D0000001E07FFFFFFFFFFF000000000002006C0003005AFFFFFFFF

case_frames() {
  local m=$work/anello_mixed.json
  expect_rc "decode anello_mixed.nmea" 0 "$decode" <"$data/anello_mixed.nmea"
  cp "$work/out" "$m"
  expect_eq "43 frames and 125 sentences" "43 125" \
    "$(grep -c '"type":"AB00"' "$m") $(grep -vc '"type":"AB00"' "$m")"
  expect_eq "the seed frame, after the first sentence" \
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
  expect_eq "the frame's payload is the seed's, but for the air temperature" \
    "${seed_frame:16:88}7FFFFFFF" "$(tail -c 48 "$work/out" | od -An -tx1 | tr -d ' \n' | tr a-f A-F)"
  expect_eq "frame errors name the field" "$(printf '%s\n' \
    'seawire-encode: line 2: AB00 field 1 (heading_deg) 361: out_of_range: value outside the range the spec allows' \
    'seawire-encode: line 3: AB00: unknown key "latitude_deg" (not a field of AB00)')" "$(cat "$work/err")"
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
    'seawire-encode: line 8: CPNVG field 2 (latitude) "north": bad_latitude: latitude is not DDMM.mmm within 90 degrees' \
    'seawire-encode: line 12: unknown_address: no known message is "XXABC" (and there is no "fields" array to send it as is)' \
    'seawire-encode: line 13: XXABC field 1 (fields): bad_text: text contains a character the field may not carry' \
    'seawire-encode: line 15: RXHRB field 2 (time) "16:12:29.5": bad_time: time is not hhmmss[.fff]' \
    'seawire-encode: line 16: BPSTS field 3 (message) "all good, really": bad_text: text contains a character the field may not carry')" \
    "$(cat "$work/err")"
}

"case_$case_name"
if ((failures > 0)); then
  echo "$case_name: $failures check(s) failed" >&2
  exit 1
fi
echo "$case_name: ok"
