# SPDX-License-Identifier: BSL-1.0
"""seawire-decode on CAN logs of NMEA 2000 traffic, checked against independent decoders.

    n2k_test.py <seawire-decode> <tests/data/n2k> <case>

canboat  every NN_*.in decoded, each message compared with canboat's analyzer output for the
         same input (NN_*.out.json, analyzer -json -si -camel -empty): header, time, and every
         field through the mapping table below.
layout   a decoder written here from the bit layouts of docs N2K.md (sections 1-7 and 10-11),
         not from the library: it parses the log lines, reassembles fast packets and decodes
         every PGN of seawire itself, and must agree with seawire-decode value for value.
errors   malformed lines among good ones: one error object per bad line, the good lines still
         decoded, exit status 1, fast-packet drops counted by --stats; --input and --log-format.
"""

import calendar
import datetime
import glob
import json
import os
import re
import sys
from decimal import Decimal

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "common"))
import harness
from harness import check

DECODE, DATA, CASE = sys.argv[1], sys.argv[2], sys.argv[3]
compared = 0  # values compared, reported at the end


def run(args, data, want_rc=None):
    return harness.run([DECODE, *args], data, want_rc)


def exact(text):
    """JSON with every fractional number as a Decimal, so values compare digit for digit."""
    return json.loads(text, parse_float=Decimal)


def vectors():
    names = sorted(glob.glob(os.path.join(DATA, "[0-9][0-9]_*.in")))
    check(len(names) >= 10, f"only {len(names)} test vectors in {DATA}")
    return names


def decode_file(path, args=()):
    with open(path, "rb") as f:
        p = run(list(args), f.read())
    check(p.returncode == 0, f"{os.path.basename(path)}: exit status {p.returncode}: "
          f"{p.stdout[:300]!r} {p.stderr[:300]!r}")
    return [exact(line) for line in p.stdout.decode().splitlines()]


def is_number(v):
    return isinstance(v, (int, Decimal)) and not isinstance(v, bool)


NULLS = (None, "out_of_range", "reserved")  # all shown as null by canboat -empty
META = {"type", "time_s", "interface", "direction", "prio", "src", "dst"}
FAST_PACKET = {127489, 128275, 130578, 127506, 129284, 130577}
FAST_PACKET |= {127237, 129038, 129039}  # lookups
FAST_PACKET |= {126464, 129540, 129029}  # repeating groups, 64-bit fields
FAST_PACKET |= {126996, 126998, 129794, 129809, 129810}  # strings
FAST_PACKET |= {126208}  # a layout per function code
# A PGN seawire does not describe travels as the standard lists it: as fast packets the PGNs
# canboat's database marks "Fast" (below) and the two proprietary fast-packet ranges whole
# (126720-126975, 130816-131071); every other one as single frames.
CANBOAT_FAST = {126208, 126464, *range(126983, 126989), 126996, 126998, 127233, 127237,
                *range(127489, 127492), *range(127494, 127499), 127503, 127504, 127506, 127507,
                *range(127509, 127515), 128275, 128520, 128538, 129029, *range(129038, 129042),
                129044, 129045, 129284, 129285, 129301, 129302, 129538, *range(129540, 129543),
                129545, 129547, 129549, 129551, 129556, *range(129792, 129817),
                *range(130052, 130055), 130060, 130061, *range(130064, 130075),
                *range(130320, 130325), 130329, 130330, *range(130561, 130576), 130577, 130578,
                130580, 130581, 130583, 130584, 130586}
# canboat's pseudo-PGNs: a gateway's own messages written among the bus's (any number past 18
# bits), skipped by seawire.
PSEUDO_PGNS = range(0x40000, 1 << 32)


def travels_fast(pgn):
    return (pgn in FAST_PACKET or pgn in CANBOAT_FAST or 126720 <= pgn <= 126975
            or 130816 <= pgn <= 131071)


# ---------------------------------------------------------------------------------------------
# Lookup and flag names: ours (snake_case) -> canboat's display names. Written here, not taken
# from the library, so a renamed value shows up as a failure.

ENGINE_INSTANCE = {0: "Single Engine or Dual Engine Port", 1: "Dual Engine Starboard"}
WATER_REFERENCE = {"paddle_wheel": "Paddle wheel", "pitot_tube": "Pitot tube",
                   "doppler": "Doppler", "correlation": "Correlation (ultra sound)",
                   "electro_magnetic": "Electro Magnetic"}
TEMPERATURE_SOURCE = {
    "sea": "Sea Temperature", "outside": "Outside Temperature",
    "inside": "Inside Temperature", "engine_room": "Engine Room Temperature",
    "main_cabin": "Main Cabin Temperature", "live_well": "Live Well Temperature",
    "bait_well": "Bait Well Temperature", "refrigeration": "Refrigeration Temperature",
    "heating_system": "Heating System Temperature", "dew_point": "Dew Point Temperature",
    "apparent_wind_chill": "Apparent Wind Chill Temperature",
    "theoretical_wind_chill": "Theoretical Wind Chill Temperature",
    "heat_index": "Heat Index Temperature", "freezer": "Freezer Temperature",
    "exhaust_gas": "Exhaust Gas Temperature", "shaft_seal": "Shaft Seal Temperature"}
HUMIDITY_SOURCE = {"inside": "Inside", "outside": "Outside"}
DIRECTION_REFERENCE = {"true": "True", "magnetic": "Magnetic"}
ENGINE_STATUS_1 = {
    "check_engine": "Check Engine", "over_temperature": "Over Temperature",
    "low_oil_pressure": "Low Oil Pressure", "low_oil_level": "Low Oil Level",
    "low_fuel_pressure": "Low Fuel Pressure", "low_system_voltage": "Low System Voltage",
    "low_coolant_level": "Low Coolant Level", "water_flow": "Water Flow",
    "water_in_fuel": "Water In Fuel", "charge_indicator": "Charge Indicator",
    "preheat_indicator": "Preheat Indicator", "high_boost_pressure": "High Boost Pressure",
    "rev_limit_exceeded": "Rev Limit Exceeded", "egr_system": "EGR System",
    "throttle_position_sensor": "Throttle Position Sensor", "emergency_stop": "Emergency Stop"}
ENGINE_STATUS_2 = {
    "warning_level_1": "Warning Level 1", "warning_level_2": "Warning Level 2",
    "power_reduction": "Power Reduction", "maintenance_needed": "Maintenance Needed",
    "engine_comm_error": "Engine Comm Error",
    "sub_or_secondary_throttle": "Sub or Secondary Throttle",
    "neutral_start_protect": "Neutral Start Protect",
    "engine_shutting_down": "Engine Shutting Down"}
VARIATION_SOURCE = {"manual": "Manual", "automatic_chart": "Automatic Chart", "automatic_table": "Automatic Table", "automatic_calculation": "Automatic Calculation", "wmm_2000": "WMM 2000", "wmm_2005": "WMM 2005", "wmm_2010": "WMM 2010", "wmm_2015": "WMM 2015", "wmm_2020": "WMM 2020", "wmm_2025": "WMM 2025"}
RUDDER_DIRECTION = {"no_order": "No Order", "to_starboard": "Move to starboard", "to_port": "Move to port"}
WIND_REFERENCE = {"true_north": "True (ground referenced to North)", "magnetic": "Magnetic (ground referenced to Magnetic North)", "apparent": "Apparent", "true_boat": "True (boat referenced)", "true_water": "True (water referenced)"}
PRESSURE_SOURCE = {"atmospheric": "Atmospheric", "water": "Water", "steam": "Steam", "compressed_air": "Compressed Air", "hydraulic": "Hydraulic", "filter": "Filter", "altimeter_setting": "AltimeterSetting", "oil": "Oil", "fuel": "Fuel"}
TANK_TYPE = {"fuel": "Fuel", "water": "Water", "gray_water": "Gray water", "live_well": "Live well", "oil": "Oil", "black_water": "Black water"}
DC_SOURCE = {"battery": "Battery", "alternator": "Alternator", "converter": "Convertor", "solar_cell": "Solar cell", "wind_generator": "Wind generator"}
RESIDUAL_MODE = {"autonomous": "Autonomous", "differential": "Differential enhanced", "estimated": "Estimated", "simulator": "Simulator", "manual": "Manual"}
YES_NO = {"no": "No", "yes": "Yes"}
TIME_SOURCE = {"gps": "GPS", "glonass": "GLONASS", "radio_station": "Radio Station", "local_cesium_clock": "Local Cesium clock", "local_rubidium_clock": "Local Rubidium clock", "local_crystal_clock": "Local Crystal clock"}
GNSS_MODE = {"1d": "1D", "2d": "2D", "3d": "3D", "auto": "Auto"}
BEARING_MODE = {"great_circle": "Great Circle", "rhumb_line": "Rhumbline"}
ISO_CONTROL = {"ack": "ACK", "nak": "NAK", "access_denied": "Access Denied", "address_busy": "Address Busy"}
# strings: product information and AIS static data (the AIS lookups shared with 129038/129039)
CERTIFICATION_LEVEL = {"level_a": "Level A", "level_b": "Level B"}
AIS_MESSAGE_ID = {"scheduled_class_a_position_report": "Scheduled Class A position report",
                  "assigned_scheduled_class_a_position_report":
                      "Assigned scheduled Class A position report",
                  "interrogated_class_a_position_report": "Interrogated Class A position report",
                  "base_station_report": "Base station report",
                  "static_and_voyage_related_data": "Static and voyage related data",
                  "binary_addressed_message": "Binary addressed message",
                  "binary_acknowledgement": "Binary acknowledgement",
                  "binary_broadcast_message": "Binary broadcast message",
                  "standard_sar_aircraft_position_report": "Standard SAR aircraft position report",
                  "utc_date_inquiry": "UTC/date inquiry", "utc_date_response": "UTC/date response",
                  "safety_related_addressed_message": "Safety related addressed message",
                  "safety_related_acknowledgement": "Safety related acknowledgement",
                  "safety_related_broadcast_message": "Satety related broadcast message",
                  "interrogation": "Interrogation",
                  "assignment_mode_command": "Assignment mode command",
                  "dgnss_broadcast_binary_message": "DGNSS broadcast binary message",
                  "standard_class_b_position_report": "Standard Class B position report",
                  "extended_class_b_position_report": "Extended Class B position report",
                  "data_link_management_message": "Data link management message",
                  "aton_report": "ATON report", "channel_management": "Channel management",
                  "group_assignment_command": "Group assignment command",
                  "static_data_report": "Static data report",
                  "single_slot_binary_message": "Single slot binary message",
                  "multiple_slot_binary_message": "Multiple slot binary message",
                  "position_report_for_long_range_applications":
                      "Position report for long range applications"}
REPEAT_INDICATOR = {"initial": "Initial", "first_retransmission": "First retransmission",
                    "second_retransmission": "Second retransmission",
                    "final_retransmission": "Final retransmission"}
SHIP_TYPE = {"unavailable": "Unavailable", "wing_in_ground": "Wing In Ground",
             "wing_in_ground_hazard_cat_x": "Wing In Ground (hazard cat X)",
             "wing_in_ground_hazard_cat_y": "Wing In Ground (hazard cat Y)",
             "wing_in_ground_hazard_cat_z": "Wing In Ground (hazard cat Z)",
             "wing_in_ground_hazard_cat_os": "Wing In Ground (hazard cat OS)",
             "wing_in_ground_no_additional_information": "Wing In Ground (no additional information)",
             "fishing": "Fishing", "towing": "Towing",
             "towing_exceeds_200m_or_wider_than_25m": "Towing exceeds 200m or wider than 25m",
             "engaged_in_dredging_or_underwater_operations": "Engaged in dredging or underwater operations",
             "engaged_in_diving_operations": "Engaged in diving operations",
             "engaged_in_military_operations": "Engaged in military operations",
             "sailing": "Sailing", "pleasure": "Pleasure", "high_speed_craft": "High speed craft",
             "high_speed_craft_hazard_cat_x": "High speed craft (hazard cat X)",
             "high_speed_craft_hazard_cat_y": "High speed craft (hazard cat Y)",
             "high_speed_craft_hazard_cat_z": "High speed craft (hazard cat Z)",
             "high_speed_craft_hazard_cat_os": "High speed craft (hazard cat OS)",
             "high_speed_craft_no_additional_information": "High speed craft (no additional information)",
             "pilot_vessel": "Pilot vessel", "sar": "SAR", "tug": "Tug",
             "port_tender": "Port tender", "anti_pollution": "Anti-pollution",
             "law_enforcement": "Law enforcement", "spare": "Spare", "spare_2": "Spare #2",
             "medical": "Medical",
             "ships_and_aircraft_of_states_not_parties_to_an_armed_conflict": "Ships and aircraft of States not parties to an armed conflict",
             "passenger_ship": "Passenger ship",
             "passenger_ship_hazard_cat_x": "Passenger ship (hazard cat X)",
             "passenger_ship_hazard_cat_y": "Passenger ship (hazard cat Y)",
             "passenger_ship_hazard_cat_z": "Passenger ship (hazard cat Z)",
             "passenger_ship_hazard_cat_os": "Passenger ship (hazard cat OS)",
             "passenger_ship_no_additional_information": "Passenger ship (no additional information)",
             "cargo_ship": "Cargo ship", "cargo_ship_hazard_cat_x": "Cargo ship (hazard cat X)",
             "cargo_ship_hazard_cat_y": "Cargo ship (hazard cat Y)",
             "cargo_ship_hazard_cat_z": "Cargo ship (hazard cat Z)",
             "cargo_ship_hazard_cat_os": "Cargo ship (hazard cat OS)",
             "cargo_ship_no_additional_information": "Cargo ship (no additional information)",
             "tanker": "Tanker", "tanker_hazard_cat_x": "Tanker (hazard cat X)",
             "tanker_hazard_cat_y": "Tanker (hazard cat Y)",
             "tanker_hazard_cat_z": "Tanker (hazard cat Z)",
             "tanker_hazard_cat_os": "Tanker (hazard cat OS)",
             "tanker_no_additional_information": "Tanker (no additional information)",
             "other": "Other", "other_hazard_cat_x": "Other (hazard cat X)",
             "other_hazard_cat_y": "Other (hazard cat Y)",
             "other_hazard_cat_z": "Other (hazard cat Z)",
             "other_hazard_cat_os": "Other (hazard cat OS)",
             "other_no_additional_information": "Other (no additional information)"}
AIS_VERSION = {"itu_r_m1371_1": "ITU-R M.1371-1", "itu_r_m1371_3": "ITU-R M.1371-3",
               "itu_r_m1371_5": "ITU-R M.1371-5", "itu_r_m1371_future": "ITU-R M.1371 future edition"}
POSITION_FIX_DEVICE = {"undefined": "Default: undefined", "gps": "GPS", "glonass": "GLONASS",
                       "gps_glonass": "Combined GPS/GLONASS", "loran_c": "Loran-C",
                       "chayka": "Chayka", "integrated_navigation_system":
                           "Integrated navigation system", "surveyed": "Surveyed",
                       "galileo": "Galileo"}
DTE = {"available": "Available", "unavailable": "Not available"}
AIS_TRANSCEIVER = {"channel_a_vdl_reception": "Channel A VDL reception",
                   "channel_b_vdl_reception": "Channel B VDL reception",
                   "channel_a_vdl_transmission": "Channel A VDL transmission",
                   "channel_b_vdl_transmission": "Channel B VDL transmission",
                   "own_information_not_broadcast": "Own information not broadcast",
                   "reserved_5": "Reserved"}


PGN_LIST_FUNCTION = {"transmit": "Transmit PGN list", "receive": "Receive PGN list"}
GROUP_FUNCTION = {"request": "Request", "command": "Command", "acknowledge": "Acknowledge"}
PRIORITY_SETTING = {**{f"priority_{i}": str(i) for i in range(8)},
                    "leave_unchanged": "Leave unchanged", "reset_to_default": "Reset to default"}
PGN_ERROR_CODE = {"acknowledge": "Acknowledge", "pgn_not_supported": "PGN not supported",
                  "pgn_not_available": "PGN not available", "access_denied": "Access denied",
                  "not_supported": "Not supported", "tag_not_supported": "Tag not supported",
                  "read_or_write_not_supported": "Read or Write not supported"}
INTERVAL_ERROR_CODE = {"acknowledge": "Acknowledge",
                       "not_supported_here": "Transmit Interval/Priority not supported",
                       "interval_too_low": "Transmit Interval too low",
                       "access_denied": "Access denied", "not_supported": "Not supported"}
PARAMETER_ERROR_CODE = {"acknowledge": "Acknowledge",
                        "invalid_parameter_field": "Invalid parameter field",
                        "temporary_error": "Temporary error",
                        "parameter_out_of_range": "Parameter out of range",
                        "access_denied": "Access denied", "not_supported": "Not supported",
                        "read_or_write_not_supported": "Read or Write not supported"}
RANGE_RESIDUAL_MODE = {"used": "Range residuals were used to calculate data",
                       "calculated_after": "Range residuals were calculated after the position"}
SATELLITE_STATUS = {"not_tracked": "Not tracked", "tracked": "Tracked", "used": "Used",
                    "not_tracked_diff": "Not tracked+Diff", "tracked_diff": "Tracked+Diff",
                    "used_diff": "Used+Diff"}
GNSS_SYSTEM = {"gps": "GPS", "glonass": "GLONASS", "galileo": "Galileo", "beidou": "BeiDou",
               "qzss": "QZSS"}
GNSS_TYPE = {"gps": "GPS", "glonass": "GLONASS", "gps_glonass": "GPS+GLONASS",
             "gps_sbas": "GPS+SBAS/WAAS", "gps_sbas_glonass": "GPS+SBAS/WAAS+GLONASS",
             "chayka": "Chayka", "integrated": "integrated", "surveyed": "surveyed",
             "galileo": "Galileo"}
GNSS_METHOD = {"no_gnss": "no GNSS", "gnss_fix": "GNSS fix", "dgnss_fix": "DGNSS fix",
               "precise_gnss": "Precise GNSS", "rtk_fixed": "RTK Fixed Integer",
               "rtk_float": "RTK float", "estimated": "Estimated (DR) mode",
               "manual": "Manual Input", "simulated": "Simulate mode"}
GNSS_INTEGRITY = {"none": "No integrity checking", "safe": "Safe", "caution": "Caution",
                  "unsafe": "Unsafe"}


# ---------------------------------------------------------------------------------------------
# canboat: converters. Each takes (ours, canboat's) and returns None when they agree, else why
# not.

def null_rule(ours, theirs):
    """canboat -empty prints null for not available, out of range and reserved alike."""
    if theirs is None:
        return None if ours in NULLS or ours == [] else "canboat null, ours a value"
    if ours in NULLS:
        return "ours null/sentinel, canboat a value"
    return "continue"


def num(resolution, as_double=False):
    """Within half the resolution; as_double: or within a double's precision of canboat's value
    (canboat computes in doubles)."""
    half = Decimal(resolution) / 2

    def cmp(ours, theirs):
        r = null_rule(ours, theirs)
        if r != "continue":
            return r
        if not is_number(ours) or not is_number(theirs):
            return "not both numbers"
        tolerance = max(half, abs(Decimal(theirs)) * Decimal(2) ** -52) if as_double else half
        if abs(Decimal(ours) - Decimal(theirs)) > tolerance:
            return f"differ by more than {tolerance} (half the resolution {resolution})"
        return None
    return cmp


def lookup(names, error=None):
    """ours: a snake_case name, or the number when unnamed; canboat: its display name. error:
    canboat's name for raw value 2 of a 2-bit lookup, J1939's "error", which seawire reads as
    out_of_range."""
    def cmp(ours, theirs):
        if error is not None and ours == "out_of_range":
            return None if theirs == error else f"expected canboat {error!r}"
        r = null_rule(ours, theirs)
        if r != "continue":
            return r
        want = names.get(ours, ours if is_number(ours) else f"<no canboat name for {ours!r}>")
        return None if want == theirs else f"expected canboat {want!r}"
    return cmp


def flag_set(names):
    """ours: array of names (bit_N when unnamed); canboat: array of display names, null when no
    bit is set; an unnamed bit as the bit's value (bit_8 is 256: canboat's analyzer, checked)."""
    def cmp(ours, theirs):
        if ours is None:  # not sent (a short message): canboat null too
            return None if theirs is None else "ours null (not sent), canboat has bits"
        if not isinstance(ours, list):
            return "ours not an array"
        if theirs is None:
            return None if ours == [] else "canboat null (no bit set), ours has bits"
        want = []
        for n in ours:
            m = re.fullmatch(r"bit_(\d+)", n)
            want.append(1 << int(m.group(1)) if m else
                        names.get(n, f"<no canboat name for {n!r}>"))
        return None if want == theirs else f"expected canboat {want!r}"
    return cmp


def hms_seconds(text):
    h, m, s = text.split(":")
    return int(h) * 3600 + int(m) * 60 + Decimal(s)


def hours(ours, theirs):
    """totalEngineHours: canboat "hhhh:mm:ss" text; ours seconds (resolution 1 s)."""
    r = null_rule(ours, theirs)
    if r != "continue":
        return r
    if not is_number(ours):
        return "ours not a number"
    return None if hms_seconds(theirs) == ours else f"canboat {hms_seconds(theirs)} s"


def duration(ours, theirs):
    """canboat "[-]h:mm:ss" text (any number of hours); ours seconds."""
    r = null_rule(ours, theirs)
    if r != "continue":
        return r
    if not is_number(ours):
        return "ours not a number"
    s = hms_seconds(theirs.lstrip("-")) * (-1 if theirs.startswith("-") else 1)
    return None if s == ours else f"canboat {s} s"


def date(ours, theirs):
    """canboat "2024.07.03"; ours "2024-07-03"."""
    r = null_rule(ours, theirs)
    if r != "continue":
        return r
    return None if theirs.replace(".", "-") == ours else "dates differ"


def time_of_day(ours, theirs):
    """Both "hh:mm:ss.ffff"; equal within half of the 0.0001 s resolution."""
    r = null_rule(ours, theirs)
    if r != "continue":
        return r
    if abs(hms_seconds(ours) - hms_seconds(theirs)) > Decimal("0.00005"):
        return "times differ"
    return None


def same(ours, theirs):
    r = null_rule(ours, theirs)
    return r if r != "continue" else (None if ours == theirs else "differ")


# ---- lookups whose names sit in the sentinel range or depend on another field ----
# The ISO NAME's manufacturer and device function texts (canboat's), from a data file beside the
# vectors; our names are those texts in snake_case, by the rule below (not the library's code).
with open(os.path.join(DATA, "iso_name_codes.json")) as f:
    ISO_CODES = json.load(f)
MANUFACTURERS = {int(k): v for k, v in ISO_CODES["manufacturer_codes"].items()}
DEVICE_FUNCTIONS = {(k, v): t for k, v, t in ISO_CODES["device_functions"]}


def snake(text):
    text = text.replace("&", " and ").replace("+", " plus ")
    return re.sub(r"[^A-Za-z0-9]+", "_", text).strip("_").lower()


DEVICE_CLASS = {"reserved_2000": "Reserved for 2000 Use", "system_tools": "System tools",
                "safety": "Safety systems", "internetwork": "Internetwork device",
                "electrical_distribution": "Electrical Distribution",
                "electrical_generation": "Electrical Generation",
                "steering_and_control_surfaces": "Steering and Control surfaces",
                "propulsion": "Propulsion", "navigation": "Navigation",
                "communication": "Communication",
                "sensor_communication_interface": "Sensor Communication Interface",
                "instrumentation": "Instrumentation/general systems",
                "external_environment": "External Environment",
                "internal_environment": "Internal Environment",
                "deck_cargo_fishing": "Deck + cargo + fishing equipment systems",
                "human_interface": "Human Interface", "display": "Display",
                "entertainment": "Entertainment"}
INDUSTRY = {"global": "Global", "highway": "Highway", "agriculture": "Agriculture",
            "construction": "Construction", "marine": "Marine Industry",
            "industrial": "Industrial"}
CONTROLLER_STATE = {"error_active": "Error Active", "error_passive": "Error Passive",
                    "bus_off": "Bus Off"}
EQUIPMENT_STATUS = {"operational": "Operational", "fault": "Fault"}
GEAR = {"forward": "Forward", "neutral": "Neutral", "reverse": "Reverse"}
STEERING_MODE = {"main_steering": "Main Steering", "non_follow_up": "Non-Follow-Up Device",
                 "follow_up": "Follow-Up Device",
                 "heading_control_standalone": "Heading Control Standalone",
                 "heading_control": "Heading Control", "track_control": "Track Control"}
TURN_MODE = {"rudder_limit_controlled": "Rudder limit controlled",
             "turn_rate_controlled": "Turn rate controlled",
             "radius_controlled": "Radius controlled"}
TRANSMISSION_STATUS = {"check_transmission": "Check Transmission",
                       "over_temperature": "Over Temperature",
                       "low_oil_pressure": "Low Oil Pressure", "low_oil_level": "Low Oil Level",
                       "sail_drive": "Sail Drive"}
POSITION_ACCURACY = {"low": "Low", "high": "High"}
RAIM = {"not_in_use": "not in use", "in_use": "in use"}
TIME_STAMP = {"unavailable": "Not available", "manual_input": "Manual input mode",
              "dead_reckoning": "Dead reckoning mode",
              "positioning_inoperative": "Positioning system is inoperative"}
NAV_STATUS = {"under_way_using_engine": "Under way using engine", "at_anchor": "At anchor",
              "not_under_command": "Not under command",
              "restricted_maneuverability": "Restricted maneuverability",
              "constrained_by_draught": "Constrained by her draught", "moored": "Moored",
              "aground": "Aground", "engaged_in_fishing": "Engaged in Fishing",
              "under_way_sailing": "Under way sailing",
              "hazardous_material_high_speed": "Hazardous material - High Speed",
              "hazardous_material_wing_in_ground": "Hazardous material - Wing in Ground",
              "towing_astern": "Power-driven vessel towing astern",
              "pushing_ahead_or_towing_alongside":
                  "Power-driven vessel pushing ahead or towing alongside",
              "ais_sart": "AIS-SART"}
SPECIAL_MANEUVER = {"unavailable": "Not available",
                    "not_engaged": "Not engaged in special maneuver",
                    "engaged": "Engaged in special maneuver", "reserved_3": "Reserved"}
UNIT_TYPE = {"sotdma": "SOTDMA", "cs": "CS"}
AIS_BAND = {"top_525_khz": "Top 525 kHz of marine band", "entire_marine_band": "Entire marine band"}
AIS_MODE = {"autonomous": "Autonomous", "assigned": "Assigned"}
AIS_COMM_STATE = {"sotdma": "SOTDMA", "itdma": "ITDMA"}


def snake_of_text(table):
    """ours: the snake_case form of canboat's text, which must be one of `table`'s texts (the
    value itself is checked by the layout case); or the number when canboat has no text."""
    texts = set(table.values())

    def cmp(ours, theirs):
        r = null_rule(ours, theirs)
        if r != "continue":
            return r
        if is_number(ours):
            return None if ours == theirs else "numbers differ"
        if theirs not in texts:
            return f"canboat {theirs!r} is no text of the table"
        return None if snake(theirs) == ours else f"expected {snake(theirs)!r}"
    return cmp


def mmsi(ours, theirs):
    """canboat: the MMSI as 9-digit text ("244100633", "002442000"); ours the number."""
    r = null_rule(ours, theirs)
    if r != "continue":
        return r
    if not (isinstance(theirs, str) and theirs.isdigit() and len(theirs) >= 9):
        return f"canboat {theirs!r} is no 9-digit text"
    return None if is_number(ours) and int(theirs) == ours else "MMSIs differ"


def binary(ours, theirs):
    """canboat: the field's bytes in hex, first byte first ("53 2F 00"); ours the number."""
    if theirs is None:
        return "canboat null for a field without sentinels"
    n = int.from_bytes(bytes.fromhex(theirs.replace(" ", "")), "little")
    return None if is_number(ours) and n == ours else f"canboat {n}"


# 129038 and 129039 share their first 13 fields.
AIS_POSITION_FIELDS = {
    "message_id": ("messageId", lookup(AIS_MESSAGE_ID)),
    "repeat_indicator": ("repeatIndicator", lookup(REPEAT_INDICATOR)),
    "user_id": ("userId", mmsi),
    "longitude_deg": ("longitude", num("0.0000001")),
    "latitude_deg": ("latitude", num("0.0000001")),
    "position_accuracy": ("positionAccuracy", lookup(POSITION_ACCURACY)),
    "raim": ("raim", lookup(RAIM)),
    "time_stamp": ("timeStamp", lookup(TIME_STAMP)),
    "cog_rad": ("cog", num("0.0001")),
    "sog_mps": ("sog", num("0.01")),
    "communication_state": ("communicationState", binary),
    "transceiver_information": ("aisTransceiverInformation", lookup(AIS_TRANSCEIVER)),
    "heading_rad": ("heading", num("0.0001")),
}


def text(ours, theirs):
    """A string: the same characters (ours escaped in JSON, canboat's raw); null for both when
    the text is empty (padding only) or not sent."""
    if ours is None or theirs is None:
        return None if ours is None and theirs is None else "one null, the other a text"
    return None if ours == theirs else "texts differ"


def num64(resolution):
    """A 64-bit field: canboat computes in double, so a value past 2^53 steps is only as exact as
    a double (53 bits); within half the resolution otherwise."""
    return num(resolution, as_double=True)


def group(fields):
    """ours: an array of objects; canboat: "list", an array of objects (absent for none). fields:
    our member -> (canboat member, converter), as for a PGN. A repetition the payload cut short:
    canboat leaves out the fields past the payload's end and reads the one cut in two from the
    bytes there are; seawire gives null for both (not held in full). So the last field canboat
    shows of the last repetition may be null in ours (the layout case checks it exactly)."""
    def cmp(ours, theirs):
        if not isinstance(ours, list):
            return "ours not an array"
        if theirs is None:
            theirs = []
        if len(ours) != len(theirs):
            return f"{len(ours)} repetitions, canboat {len(theirs)}"
        for i, (o, t) in enumerate(zip(ours, theirs)):
            unmapped = ({k for k in t if not CANBOAT_IGNORED.fullmatch(k)}
                        - {c for c, _ in fields.values()})
            if unmapped:
                return f"repetition {i}: canboat fields not in the mapping: {sorted(unmapped)}"
            if set(o) != set(fields):
                return f"repetition {i}: our fields {sorted(o)}"
            names = list(fields)
            shown = [k for k in names if fields[k][0] in t]
            for k in names:
                their_name, c = fields[k]
                if their_name not in t:
                    if o[k] is not None:
                        return f"repetition {i}: canboat has no {their_name}, ours {o[k]!r}"
                    continue
                if i == len(ours) - 1 and shown and k == shown[-1] and o[k] is None:
                    continue  # the field cut in two by the payload's end
                why = c(o[k], t[their_name])
                if why is not None:
                    return f"repetition {i}: {k} = {o[k]!r} vs {t[their_name]!r}: {why}"
        return None
    return cmp


# Per PGN: our field -> (canboat field, converter). Resolutions are N2K.md's (sections 2-7).
CANBOAT_FIELDS = {
    127488: {
        "instance": ("instance", lookup(ENGINE_INSTANCE)),
        "speed_rpm": ("speed", num("0.25")),
        "boost_pressure_pa": ("boostPressure", num("100")),
        "tilt_trim_pct": ("tiltTrim", num("1")),
    },
    127489: {
        "instance": ("instance", lookup(ENGINE_INSTANCE)),
        "oil_pressure_pa": ("oilPressure", num("100")),
        "oil_temperature_k": ("oilTemperature", num("0.1")),
        "temperature_k": ("temperature", num("0.01")),
        "alternator_potential_v": ("alternatorPotential", num("0.01")),
        "fuel_rate_lph": ("fuelRate", num("0.1")),
        "total_engine_hours_s": ("totalEngineHours", hours),
        "coolant_pressure_pa": ("coolantPressure", num("100")),
        "fuel_pressure_pa": ("fuelPressure", num("1000")),
        "discrete_status_1": ("discreteStatus1", flag_set(ENGINE_STATUS_1)),
        "discrete_status_2": ("discreteStatus2", flag_set(ENGINE_STATUS_2)),
        "engine_load_pct": ("engineLoad", num("1")),
        "engine_torque_pct": ("engineTorque", num("1")),
    },
    128259: {
        "sid": ("sid", num("1")),
        "speed_water_mps": ("speedWaterReferenced", num("0.01")),
        "speed_ground_mps": ("speedGroundReferenced", num("0.01")),
        "speed_type": ("speedWaterReferencedType", lookup(WATER_REFERENCE)),
        "speed_direction": ("speedDirection", num("1")),
    },
    128275: {
        "date": ("date", date),
        "time": ("time", time_of_day),
        "log_m": ("log", num("1")),
        "trip_log_m": ("tripLog", num("1")),
    },
    130311: {
        "sid": ("sid", num("1")),
        "temperature_source": ("temperatureSource", lookup(TEMPERATURE_SOURCE)),
        "humidity_source": ("humiditySource", lookup(HUMIDITY_SOURCE)),
        "temperature_k": ("temperature", num("0.01")),
        "humidity_pct": ("humidity", num("0.004")),
        "atmospheric_pressure_pa": ("atmosphericPressure", num("100")),
    },
    130578: {
        "longitudinal_water_mps": ("longitudinalSpeedWaterReferenced", num("0.001")),
        "transverse_water_mps": ("transverseSpeedWaterReferenced", num("0.001")),
        "longitudinal_ground_mps": ("longitudinalSpeedGroundReferenced", num("0.001")),
        "transverse_ground_mps": ("transverseSpeedGroundReferenced", num("0.001")),
        "stern_water_mps": ("sternSpeedWaterReferenced", num("0.001")),
        "stern_ground_mps": ("sternSpeedGroundReferenced", num("0.001")),
    },
    127250: {
        "sid": ("sid", num("1")),
        "heading_rad": ("heading", num("0.0001")),
        "deviation_rad": ("deviation", num("0.0001")),
        "variation_rad": ("variation", num("0.0001")),
        "reference": ("reference", lookup(DIRECTION_REFERENCE, "Error")),
    },
    127251: {
        "sid": ("sid", num("1")),
        "rate_radps": ("rate", num("3.125e-8")),
    },
    127257: {
        "sid": ("sid", num("1")),
        "yaw_rad": ("yaw", num("0.0001")),
        "pitch_rad": ("pitch", num("0.0001")),
        "roll_rad": ("roll", num("0.0001")),
    },
    127258: {
        "sid": ("sid", num("1")),
        "source": ("source", lookup(VARIATION_SOURCE)),
        "age_of_service": ("ageOfService", date),
        "variation_rad": ("variation", num("0.0001")),
    },
    128267: {
        "sid": ("sid", num("1")),
        "depth_m": ("depth", num("0.01")),
        "offset_m": ("offset", num("0.001")),
        "range_m": ("range", num("10")),
    },
    129025: {
        "latitude_deg": ("latitude", num("0.0000001")),
        "longitude_deg": ("longitude", num("0.0000001")),
    },
    129026: {
        "sid": ("sid", num("1")),
        "cog_reference": ("cogReference", lookup(DIRECTION_REFERENCE, "Error")),
        "cog_rad": ("cog", num("0.0001")),
        "sog_mps": ("sog", num("0.01")),
    },
    127245: {
        "instance": ("instance", num("1")),
        "direction_order": ("directionOrder", lookup(RUDDER_DIRECTION)),
        "angle_order_rad": ("angleOrder", num("0.0001")),
        "position_rad": ("position", num("0.0001")),
    },
    130306: {
        "sid": ("sid", num("1")),
        "wind_speed_mps": ("windSpeed", num("0.01")),
        "wind_angle_rad": ("windAngle", num("0.0001")),
        "reference": ("reference", lookup(WIND_REFERENCE)),
    },
    130312: {
        "sid": ("sid", num("1")),
        "instance": ("instance", num("1")),
        "source": ("source", lookup(TEMPERATURE_SOURCE)),
        "actual_temperature_k": ("actualTemperature", num("0.01")),
        "set_temperature_k": ("setTemperature", num("0.01")),
    },
    130313: {
        "sid": ("sid", num("1")),
        "instance": ("instance", num("1")),
        "source": ("source", lookup(HUMIDITY_SOURCE)),
        "actual_humidity_pct": ("actualHumidity", num("0.004")),
        "set_humidity_pct": ("setHumidity", num("0.004")),
    },
    130314: {
        "sid": ("sid", num("1")),
        "instance": ("instance", num("1")),
        "source": ("source", lookup(PRESSURE_SOURCE)),
        "pressure_pa": ("pressure", num("0.1")),
    },
    130316: {
        "sid": ("sid", num("1")),
        "instance": ("instance", num("1")),
        "source": ("source", lookup(TEMPERATURE_SOURCE)),
        "temperature_k": ("temperature", num("0.001")),
        "set_temperature_k": ("setTemperature", num("0.1")),
    },
    127508: {
        "instance": ("instance", num("1")),
        "voltage_v": ("voltage", num("0.01")),
        "current_a": ("current", num("0.1")),
        "temperature_k": ("temperature", num("0.01")),
        "sid": ("sid", num("1")),
    },
    127505: {
        "instance": ("instance", num("1")),
        "fluid_type": ("type", lookup(TANK_TYPE)),
        "level_pct": ("level", num("0.004")),
        "capacity_l": ("capacity", num("0.1")),
    },
    127506: {
        "sid": ("sid", num("1")),
        "instance": ("instance", num("1")),
        "dc_type": ("dcType", lookup(DC_SOURCE)),
        "state_of_charge_pct": ("stateOfCharge", num("1")),
        "state_of_health_pct": ("stateOfHealth", num("1")),
        "time_remaining_s": ("timeRemaining", duration),
        "ripple_voltage_v": ("rippleVoltage", num("0.001")),
        "remaining_capacity_ah": ("remainingCapacity", num("1")),
    },
    129283: {
        "sid": ("sid", num("1")),
        "xte_mode": ("xteMode", lookup(RESIDUAL_MODE)),
        "navigation_terminated": ("navigationTerminated", lookup(YES_NO)),
        "xte_m": ("xte", num("0.01")),
    },
    126992: {
        "sid": ("sid", num("1")),
        "source": ("source", lookup(TIME_SOURCE)),
        "date": ("date", date),
        "time": ("time", time_of_day),
    },
    129033: {
        "date": ("date", date),
        "time": ("time", time_of_day),
        "local_offset_s": ("localOffset", duration),
    },
    129539: {
        "sid": ("sid", num("1")),
        "desired_mode": ("desiredMode", lookup(GNSS_MODE)),
        "actual_mode": ("actualMode", lookup(GNSS_MODE)),
        "hdop": ("hdop", num("0.01")),
        "vdop": ("vdop", num("0.01")),
        "tdop": ("tdop", num("0.01")),
    },
    129284: {
        "sid": ("sid", num("1")),
        "distance_to_waypoint_m": ("distanceToWaypoint", num("0.01")),
        "course_bearing_reference": ("courseBearingReference", lookup(DIRECTION_REFERENCE, "Error")),
        "perpendicular_crossed": ("perpendicularCrossed", lookup(YES_NO)),
        "arrival_circle_entered": ("arrivalCircleEntered", lookup(YES_NO)),
        "calculation_type": ("calculationType", lookup(BEARING_MODE)),
        "eta_time": ("etaTime", time_of_day),
        "eta_date": ("etaDate", date),
        "bearing_origin_to_destination_rad": ("bearingOriginToDestinationWaypoint", num("0.0001")),
        "bearing_position_to_destination_rad": ("bearingPositionToDestinationWaypoint", num("0.0001")),
        "origin_waypoint_number": ("originWaypointNumber", num("1")),
        "destination_waypoint_number": ("destinationWaypointNumber", num("1")),
        "destination_latitude_deg": ("destinationLatitude", num("0.0000001")),
        "destination_longitude_deg": ("destinationLongitude", num("0.0000001")),
        "waypoint_closing_velocity_mps": ("waypointClosingVelocity", num("0.01")),
    },
    130577: {
        "data_mode": ("dataMode", lookup(RESIDUAL_MODE)),
        "cog_reference": ("cogReference", lookup(DIRECTION_REFERENCE, "Error")),
        "sid": ("sid", num("1")),
        "cog_rad": ("cog", num("0.0001")),
        "sog_mps": ("sog", num("0.01")),
        "heading_rad": ("heading", num("0.0001")),
        "speed_water_mps": ("speedThroughWater", num("0.01")),
        "set_rad": ("set", num("0.0001")),
        "drift_mps": ("drift", num("0.01")),
    },
    59904: {
        "requested_pgn": ("pgn", num("1")),
    },
    59392: {
        "control": ("control", lookup(ISO_CONTROL)),
        "group_function": ("groupFunction", num("1")),
        "acknowledged_pgn": ("pgn", num("1")),
    },
    # lookups whose names sit in the sentinel range or depend on another field
    60928: {
        "unique_number": ("uniqueNumber", num("1")),
        "manufacturer_code": ("manufacturerCode", snake_of_text(MANUFACTURERS)),
        "device_instance_lower": ("deviceInstanceLower", num("1")),
        "device_instance_upper": ("deviceInstanceUpper", num("1")),
        "device_function": ("deviceFunction", snake_of_text(DEVICE_FUNCTIONS)),
        "device_class": ("deviceClass", lookup(DEVICE_CLASS)),
        "system_instance": ("systemInstance", num("1")),
        "industry_group": ("industryGroup", lookup(INDUSTRY)),
        "arbitrary_address_capable": ("arbitraryAddressCapable", lookup(YES_NO)),
    },
    126993: {
        "data_transmit_offset_s": ("dataTransmitOffset", duration),
        "sequence_counter": ("sequenceCounter", num("1")),
        "controller_1_state": ("controller1State", lookup(CONTROLLER_STATE)),
        "controller_2_state": ("controller2State", lookup(CONTROLLER_STATE)),
        "equipment_status": ("equipmentStatus", lookup(EQUIPMENT_STATUS)),
    },
    127237: {
        "rudder_limit_exceeded": ("rudderLimitExceeded", lookup(YES_NO)),
        "off_heading_limit_exceeded": ("offHeadingLimitExceeded", lookup(YES_NO)),
        "off_track_limit_exceeded": ("offTrackLimitExceeded", lookup(YES_NO)),
        "override": ("override", lookup(YES_NO)),
        "steering_mode": ("steeringMode", lookup(STEERING_MODE)),
        "turn_mode": ("turnMode", lookup(TURN_MODE)),
        "heading_reference": ("headingReference", lookup(DIRECTION_REFERENCE, "Error")),
        "commanded_rudder_direction": ("commandedRudderDirection", lookup(RUDDER_DIRECTION)),
        "commanded_rudder_angle_rad": ("commandedRudderAngle", num("0.0001")),
        "heading_to_steer_rad": ("headingToSteerCourse", num("0.0001")),
        "track_rad": ("track", num("0.0001")),
        "rudder_limit_rad": ("rudderLimit", num("0.0001")),
        "off_heading_limit_rad": ("offHeadingLimit", num("0.0001")),
        "radius_of_turn_order_m": ("radiusOfTurnOrder", num("1")),
        "rate_of_turn_order_radps": ("rateOfTurnOrder", num("0.00003125")),
        "off_track_limit_m": ("offTrackLimit", num("1")),
        "vessel_heading_rad": ("vesselHeading", num("0.0001")),
    },
    127252: {
        "sid": ("sid", num("1")),
        "heave_m": ("heave", num("0.01")),
    },
    127493: {
        "instance": ("instance", lookup(ENGINE_INSTANCE)),
        "transmission_gear": ("transmissionGear", lookup(GEAR)),
        "oil_pressure_pa": ("oilPressure", num("100")),
        "oil_temperature_k": ("oilTemperature", num("0.1")),
        "discrete_status_1": ("discreteStatus1", flag_set(TRANSMISSION_STATUS)),
    },
    129038: {
        **AIS_POSITION_FIELDS,
        "rate_of_turn_radps": ("rateOfTurn", num("0.00003125")),
        "nav_status": ("navStatus", lookup(NAV_STATUS)),
        "special_maneuver": ("specialManeuverIndicator", lookup(SPECIAL_MANEUVER)),
        "sid": ("sequenceId", num("1")),
    },
    129039: {
        **AIS_POSITION_FIELDS,
        "unit_type": ("unitType", lookup(UNIT_TYPE)),
        "integrated_display": ("integratedDisplay", lookup(YES_NO)),
        "dsc": ("dsc", lookup(YES_NO)),
        "band": ("band", lookup(AIS_BAND)),
        "can_handle_msg_22": ("canHandleMsg22", lookup(YES_NO)),
        "ais_mode": ("aisMode", lookup(AIS_MODE)),
        "ais_communication_state": ("aisCommunicationState", lookup(AIS_COMM_STATE)),
        "sid": ("sequenceId", num("1")),
    },
    # ---- strings ----
    126996: {
        "nmea2000_version": ("nmea2000Version", num("0.001")),
        "product_code": ("productCode", num("1")),
        "model_id": ("modelId", text),
        "software_version_code": ("softwareVersionCode", text),
        "model_version": ("modelVersion", text),
        "model_serial_code": ("modelSerialCode", text),
        "certification_level": ("certificationLevel", lookup(CERTIFICATION_LEVEL)),
        "load_equivalency": ("loadEquivalency", num("1")),
    },
    126998: {
        "installation_description_1": ("installationDescription1", text),
        "installation_description_2": ("installationDescription2", text),
        "manufacturer_information": ("manufacturerInformation", text),
    },
    129794: {
        "message_id": ("messageId", lookup(AIS_MESSAGE_ID)),
        "repeat_indicator": ("repeatIndicator", lookup(REPEAT_INDICATOR)),
        "user_id": ("userId", mmsi),
        "imo_number": ("imoNumber", num("1")),
        "callsign": ("callsign", text),
        "name": ("name", text),
        "type_of_ship": ("typeOfShip", lookup(SHIP_TYPE)),
        "length_m": ("length", num("0.1")),
        "beam_m": ("beam", num("0.1")),
        "position_reference_from_starboard_m": ("positionReferenceFromStarboard", num("0.1")),
        "position_reference_from_bow_m": ("positionReferenceFromBow", num("0.1")),
        "eta_date": ("etaDate", date),
        "eta_time": ("etaTime", time_of_day),
        "draft_m": ("draft", num("0.01")),
        "destination": ("destination", text),
        "ais_version_indicator": ("aisVersionIndicator", lookup(AIS_VERSION)),
        "gnss_type": ("gnssType", lookup(POSITION_FIX_DEVICE)),
        "dte": ("dte", lookup(DTE)),
        "ais_transceiver_information": ("aisTransceiverInformation", lookup(AIS_TRANSCEIVER)),
        "sequence_id": ("sequenceId", num("1")),
    },
    129809: {
        "message_id": ("messageId", lookup(AIS_MESSAGE_ID)),
        "repeat_indicator": ("repeatIndicator", lookup(REPEAT_INDICATOR)),
        "user_id": ("userId", mmsi),
        "name": ("name", text),
        "ais_transceiver_information": ("aisTransceiverInformation", lookup(AIS_TRANSCEIVER)),
        "sequence_id": ("sequenceId", num("1")),
    },
    129810: {
        "message_id": ("messageId", lookup(AIS_MESSAGE_ID)),
        "repeat_indicator": ("repeatIndicator", lookup(REPEAT_INDICATOR)),
        "user_id": ("userId", mmsi),
        "type_of_ship": ("typeOfShip", lookup(SHIP_TYPE)),
        "vendor_id": ("vendorId", text),
        "callsign": ("callsign", text),
        "length_m": ("length", num("0.1")),
        "beam_m": ("beam", num("0.1")),
        "position_reference_from_starboard_m": ("positionReferenceFromStarboard", num("0.1")),
        "position_reference_from_bow_m": ("positionReferenceFromBow", num("0.1")),
        "mothership_user_id": ("mothershipUserId", mmsi),
        "gnss_type": ("gnssType", lookup(POSITION_FIX_DEVICE)),
        "ais_transceiver_information": ("aisTransceiverInformation", lookup(AIS_TRANSCEIVER)),
        "sequence_id": ("sequenceId", num("1")),
    },
    126464: {
        "function_code": ("functionCode", lookup(PGN_LIST_FUNCTION)),
        "pgns": ("list", group({"pgn": ("pgn", num("1"))})),
    },
    129540: {
        "sid": ("sid", num("1")),
        "range_residual_mode": ("rangeResidualMode", lookup(RANGE_RESIDUAL_MODE)),
        "sats_in_view": ("satsInView", num("1")),
        "satellites": ("list", group({
            "prn": ("prn", num("1")),
            "elevation_rad": ("elevation", num("0.0001")),
            "azimuth_rad": ("azimuth", num("0.0001")),
            "snr_db": ("snr", num("0.01")),
            "range_residuals_m": ("rangeResiduals", num("0.00001")),
            "status": ("status", lookup(SATELLITE_STATUS)),
            "gnss_system": ("gnssSystem", lookup(GNSS_SYSTEM)),
        })),
    },
    129029: {
        "sid": ("sid", num("1")),
        "date": ("date", date),
        "time": ("time", time_of_day),
        # canboat prints 7 fraction digits of a degree (and 6 of a metre)
        "latitude_deg": ("latitude", num64("0.0000001")),
        "longitude_deg": ("longitude", num64("0.0000001")),
        "altitude_m": ("altitude", num64("0.000001")),
        "gnss_type": ("gnssType", lookup(GNSS_TYPE)),
        "method": ("method", lookup(GNSS_METHOD)),
        "integrity": ("integrity", lookup(GNSS_INTEGRITY)),
        "number_of_svs": ("numberOfSvs", num("1")),
        "hdop": ("hdop", num("0.01")),
        "pdop": ("pdop", num("0.01")),
        "geoidal_separation_m": ("geoidalSeparation", num("0.01")),
        "reference_stations": ("referenceStations", num("1")),
        "stations": ("list", group({
            "station_type": ("referenceStationType", lookup(GNSS_TYPE)),
            "station_id": ("referenceStationId", num("1")),
            "age_of_corrections_s": ("ageOfDgnssCorrections", duration),
        })),
    },
}


def parameter_pairs(ours, theirs):
    """A group function's parameter pairs: ours the bytes as hex; canboat decodes each value as
    the field it names of the PGN the message names, from its own database, which seawire does
    not (a value is as wide as that field). Checked: no pairs, no list; otherwise canboat's first
    pair names the field our first byte holds."""
    if not isinstance(ours, str):
        return "ours not a hex string"
    if not theirs:
        return None if ours == "" else f"ours {ours!r}, canboat no pairs"
    first = theirs[0].get("parameter")
    if not ours:
        return "ours no bytes, canboat has pairs"
    return None if first == int(ours[:2], 16) else f"first field {int(ours[:2], 16)}, canboat {first}"


# A PGN whose layout its first byte picks (126208's function code): per code, the mapping. A code
# without one is raw in ours (canboat may know it: its Read and Write Fields layouts).
CANBOAT_FIELDS_BY_CODE = {
    126208: {
        0: {
            "function_code": ("functionCode", lookup(GROUP_FUNCTION)),
            "pgn": ("pgn", num("1")),
            "transmission_interval_s": ("transmissionInterval", duration),
            "transmission_interval_offset_s": ("transmissionIntervalOffset", duration),
            "number_of_parameters": ("numberOfParameters", num("1")),
            "parameters": ("list", parameter_pairs),
        },
        1: {
            "function_code": ("functionCode", lookup(GROUP_FUNCTION)),
            "pgn": ("pgn", num("1")),
            "priority": ("priority", lookup(PRIORITY_SETTING)),
            "number_of_parameters": ("numberOfParameters", num("1")),
            "parameters": ("list", parameter_pairs),
        },
        2: {
            "function_code": ("functionCode", lookup(GROUP_FUNCTION)),
            "pgn": ("pgn", num("1")),
            "pgn_error_code": ("pgnErrorCode", lookup(PGN_ERROR_CODE)),
            "transmission_interval_priority_error_code":
                ("transmissionIntervalPriorityErrorCode", lookup(INTERVAL_ERROR_CODE)),
            "number_of_parameters": ("numberOfParameters", num("1")),
            "parameters": ("list", group({
                "parameter": ("parameter", lookup(PARAMETER_ERROR_CODE)),
            })),
        },
    },
}

# canboat lists a "reserved" field (as hex text) when the reserved bits are not all ones, named
# "reserved" and, for a PGN's later reserved fields, "reserved" with the field's number
# ("reserved6"); seawire ignores reserved bits on receive (N2K.md section 1), so it has no such
# field. Likewise spare bits (AIS's and the ISO NAME's: "spare", "spare18", 129039's regional
# application), which canboat lists when they are not zero.
CANBOAT_IGNORED = re.compile(r"reserved\d*|spare\d*|regionalApplicationB?")


# ---------------------------------------------------------------------------------------------
# Log lines, parsed here (N2K.md section 11).

CANDUMP_LOG = re.compile(r"\((\d+\.\d+)\)\s+(\S+)\s+([0-9A-Fa-f]{8})#([0-9A-Fa-f]*)")
CANDUMP = re.compile(r"\s*(\S+)\s+([0-9A-Fa-f]{8})\s+\[(\d)\]((?:\s+[0-9A-Fa-f]{2})*)\s*")
YD_RAW = re.compile(r"(\d\d):(\d\d):(\d\d(?:\.\d+)?)\s+([RT])\s+([0-9A-Fa-f]{8})"
                    r"((?:\s+[0-9A-Fa-f]{2}){0,8})\s*")
# Actisense N2K ASCII: A<hhmmss.ddd> <source, destination, priority in 5 hex digits> <PGN in hex>
# <the whole message in hex>.
ACTISENSE = re.compile(r"A(\d\d)(\d\d)(\d\d(?:\.\d+)?)\s+([0-9A-Fa-f]{5})\s+([0-9A-Fa-f]{1,5})"
                       r"\s+((?:[0-9A-Fa-f]{2})*)\s*")
ISO = re.compile(r"(\d{4})-(\d\d)-(\d\d)[T-](\d\d):(\d\d):(\d\d)(\.\d+)?(Z|[+-]\d\d:?\d\d)?")


def line_format(line):
    if line.startswith("#"):
        return "comment"
    if CANDUMP_LOG.fullmatch(line):
        return "candump_log"
    if YD_RAW.fullmatch(line):
        return "yd_raw"
    if ACTISENSE.fullmatch(line):
        return "actisense_n2k_ascii"
    if CANDUMP.fullmatch(line):
        return "candump"
    return "canboat"


def iso_seconds(text):
    """A canboat timestamp as Unix seconds (Decimal) and whether it named its zone offset
    other than Z; None when it is not of a known ISO form. No zone means UTC."""
    m = ISO.fullmatch(text)
    if not m:
        return None, False
    y, mo, d, h, mi, s, frac, zone = m.groups()
    t = Decimal(calendar.timegm((int(y), int(mo), int(d), int(h), int(mi), int(s))))
    if frac:
        t += Decimal("0" + frac)
    offset = bool(zone and zone != "Z")
    if offset:
        sign = -1 if zone[0] == "-" else 1
        hh, mm = int(zone[1:3]), int(zone[-2:])
        t -= sign * (hh * 3600 + mm * 60)
    return t, offset


def split_id(can_id):
    """prio, pgn, src, dst of a 29-bit identifier (N2K.md section 9)."""
    prio = (can_id >> 26) & 7
    dp = (can_id >> 24) & 3
    pf = (can_id >> 16) & 0xFF
    ps = (can_id >> 8) & 0xFF
    src = can_id & 0xFF
    if pf < 240:
        return prio, (dp << 16) | (pf << 8), src, ps
    return prio, (dp << 16) | (pf << 8) | ps, src, 255


def parse_line(line):
    """One log line as a frame dict: prio, pgn, src, dst, data (bytes), time (Decimal or None),
    plus interface/direction, and whether it is already a whole message (canboat FAST)."""
    m = CANDUMP_LOG.fullmatch(line)
    if m:
        prio, pgn, src, dst = split_id(int(m.group(3), 16))
        return dict(prio=prio, pgn=pgn, src=src, dst=dst, data=bytes.fromhex(m.group(4)),
                    time=Decimal(m.group(1)), extra={"interface": m.group(2)}, whole=False,
                    canboat=False)
    m = YD_RAW.fullmatch(line)
    if m:
        prio, pgn, src, dst = split_id(int(m.group(5), 16))
        t = int(m.group(1)) * 3600 + int(m.group(2)) * 60 + Decimal(m.group(3))
        return dict(prio=prio, pgn=pgn, src=src, dst=dst, data=bytes.fromhex(m.group(6)),
                    time=t, extra={"direction": m.group(4)}, whole=False, canboat=False)
    m = ACTISENSE.fullmatch(line)
    if m:
        address, pgn = int(m.group(4), 16), int(m.group(5), 16)
        src, dst, prio = address >> 12, address >> 4 & 0xFF, address & 0xF
        if not (pgn >> 8 & 0xFF) < 240:
            dst = 255  # a broadcast PGN's destination is everyone, whatever the line says
        t = int(m.group(1)) * 3600 + int(m.group(2)) * 60 + Decimal(m.group(3))
        return dict(prio=prio, pgn=pgn, src=src, dst=dst, data=bytes.fromhex(m.group(6)),
                    time=t, extra={}, whole=True, canboat=False)
    m = CANDUMP.fullmatch(line)
    if m:
        prio, pgn, src, dst = split_id(int(m.group(2), 16))
        return dict(prio=prio, pgn=pgn, src=src, dst=dst, data=bytes.fromhex(m.group(4)),
                    time=None, extra={"interface": m.group(1)}, whole=False, canboat=False)
    parts = line.split(",")
    ts, prio, pgn, src, dst, n = parts[:6]
    data = bytes(int(x, 16) for x in parts[6:])
    assert len(data) == int(n), line
    return dict(prio=int(prio), pgn=int(pgn), src=int(src), dst=int(dst), data=data,
                time=iso_seconds(ts)[0], extra={}, whole=len(data) > 8, canboat=True)


def messages(lines):
    """Whole messages from log lines (N2K.md sections 10-11), each with the time of the frame that
    completed it. Single frames as they are. canboat lines: a "# format=" header says whether a
    line is a frame (PLAIN), a whole message (FAST), or each by its length (PLAIN_MIX_FAST);
    without one, as canboat does: FAST when the first canboat line has more than 8 bytes, else
    frames until the first longer line (PLAIN_OR_FAST). Fast packets reassembled from frames in any
    order (byte 0 = sequence << 5 | frame, frame 0 byte 1 = length), as canboat's analyzer does:
    frames held before a frame 0 that would complete the packet at once are dropped (the rest of
    an earlier packet), and so are frames numbered past the count frame 0 announces."""
    out = []
    partial = {}  # (src, pgn, dst) -> [sequence, {frame: data}]
    mode = None
    for line in lines:
        if line.startswith("#"):
            m = re.fullmatch(r"# format=(\w+)\s*", line)
            if m and m.group(1).upper() in ("PLAIN", "FAST", "PLAIN_OR_FAST", "PLAIN_MIX_FAST"):
                mode = m.group(1).upper()
            continue
        f = parse_line(line)
        if f["pgn"] in PSEUDO_PGNS:
            continue  # a gateway's own message, whole whatever the log's format
        if f["canboat"]:
            n = len(f["data"])
            if mode is None:
                mode = "FAST" if n > 8 else "PLAIN_OR_FAST"
            if mode == "PLAIN_OR_FAST" and n > 8:
                mode = "FAST"
            f["whole"] = mode == "FAST" or (mode != "PLAIN" and n > 8)
        if not travels_fast(f["pgn"]) or f["whole"]:
            out.append(f)
            continue
        d = f["data"]
        if not d or (d[0] & 0x1F == 0 and len(d) < 2):
            continue  # no frame of a packet
        seq, frame = d[0] >> 5, d[0] & 0x1F
        key = (f["src"], f["pgn"], f["dst"])
        p = partial.get(key)
        if p is not None and (p[0] != seq or frame in p[1]):
            p = None  # another packet begins
        count = lambda length: 1 if length <= 6 else 1 + (length - 6 + 6) // 7
        if p is not None and frame == 0:
            need = set(range(count(d[1])))
            held = set(p[1])
            if not held <= need or (len(need) > 1 and held | {0} == need):
                p = None
        elif p is not None and 0 in p[1] and frame >= count(p[1][0][1]):
            continue  # past the packet's end
        if p is None:
            p = partial[key] = [seq, {}]
        p[1][frame] = d
        if 0 not in p[1]:
            continue
        length = p[1][0][1]
        if set(p[1]) != set(range(count(length))):
            continue
        payload = bytearray(p[1][0][2:8])
        for k in range(1, count(length)):
            payload += p[1][k][1:8]
        del partial[key]
        if len(payload) >= length:
            out.append(dict(f, data=bytes(payload[:length])))
    return out


# ---------------------------------------------------------------------------------------------
# The bit layouts, by hand from N2K.md sections 2-7: (our name, bit offset, bits, kind, arg).
# Kinds: u/s = unsigned/signed number with resolution arg; lookup = names by value (arg);
# flags = bit names (arg, by bit number); date = days since 1970; time = 0.0001 s since
# midnight. Reserved bits are left out (ignored on receive).

U, S = "u", "s"
L_WATER = ["paddle_wheel", "pitot_tube", "doppler", "correlation", "electro_magnetic"]
L_TEMP = ["sea", "outside", "inside", "engine_room", "main_cabin", "live_well", "bait_well",
          "refrigeration", "heating_system", "dew_point", "apparent_wind_chill",
          "theoretical_wind_chill", "heat_index", "freezer", "exhaust_gas", "shaft_seal"]
L_HUM = ["inside", "outside"]
L_DIRECTION = ["true", "magnetic"]
F_STATUS_1 = ["check_engine", "over_temperature", "low_oil_pressure", "low_oil_level",
              "low_fuel_pressure", "low_system_voltage", "low_coolant_level", "water_flow",
              "water_in_fuel", "charge_indicator", "preheat_indicator", "high_boost_pressure",
              "rev_limit_exceeded", "egr_system", "throttle_position_sensor", "emergency_stop"]
F_STATUS_2 = ["warning_level_1", "warning_level_2", "power_reduction", "maintenance_needed",
              "engine_comm_error", "sub_or_secondary_throttle", "neutral_start_protect",
              "engine_shutting_down"]  # bits 8-15 unnamed: bit_8 ... bit_15
L_VARIATION_SOURCE = ["manual", "automatic_chart", "automatic_table", "automatic_calculation", "wmm_2000", "wmm_2005", "wmm_2010", "wmm_2015", "wmm_2020", "wmm_2025"]
L_RUDDER_DIRECTION = ["no_order", "to_starboard", "to_port"]
L_WIND_REFERENCE = ["true_north", "magnetic", "apparent", "true_boat", "true_water"]
L_PRESSURE_SOURCE = ["atmospheric", "water", "steam", "compressed_air", "hydraulic", "filter", "altimeter_setting", "oil", "fuel"]
L_TANK_TYPE = ["fuel", "water", "gray_water", "live_well", "oil", "black_water"]
L_DC_SOURCE = ["battery", "alternator", "converter", "solar_cell", "wind_generator"]
L_RESIDUAL_MODE = ["autonomous", "differential", "estimated", "simulator", "manual"]
L_YES_NO = ["no", "yes"]
L_TIME_SOURCE = ["gps", "glonass", "radio_station", "local_cesium_clock", "local_rubidium_clock", "local_crystal_clock"]
L_GNSS_MODE = ["1d", "2d", "3d", "auto"]
L_BEARING_MODE = ["great_circle", "rhumb_line"]
L_ISO_CONTROL = ["ack", "nak", "access_denied", "address_busy"]
# strings: lookups of 126996 and the AIS PGNs, by value (None: no name, shown as the number)
L_CERTIFICATION = ["level_a", "level_b"]
L_AIS_MESSAGE = [None, "scheduled_class_a_position_report",
                 "assigned_scheduled_class_a_position_report",
                 "interrogated_class_a_position_report", "base_station_report",
                 "static_and_voyage_related_data", "binary_addressed_message",
                 "binary_acknowledgement", "binary_broadcast_message",
                 "standard_sar_aircraft_position_report", "utc_date_inquiry", "utc_date_response",
                 "safety_related_addressed_message", "safety_related_acknowledgement",
                 "safety_related_broadcast_message", "interrogation", "assignment_mode_command",
                 "dgnss_broadcast_binary_message", "standard_class_b_position_report",
                 "extended_class_b_position_report", "data_link_management_message",
                 "aton_report", "channel_management", "group_assignment_command",
                 "static_data_report", "single_slot_binary_message",
                 "multiple_slot_binary_message", "position_report_for_long_range_applications"]
L_REPEAT = ["initial", "first_retransmission", "second_retransmission", "final_retransmission"]
L_SHIP_TYPE = [None] * 100
L_SHIP_TYPE[0] = "unavailable"
for _base, _kind in ((20, "wing_in_ground"), (40, "high_speed_craft"), (60, "passenger_ship"),
                     (70, "cargo_ship"), (80, "tanker"), (90, "other")):
    L_SHIP_TYPE[_base] = _kind
    for _k, _cat in enumerate(("x", "y", "z", "os"), 1):
        L_SHIP_TYPE[_base + _k] = f"{_kind}_hazard_cat_{_cat}"
    L_SHIP_TYPE[_base + 9] = f"{_kind}_no_additional_information"
for _k, _n in enumerate(["fishing", "towing", "towing_exceeds_200m_or_wider_than_25m",
                         "engaged_in_dredging_or_underwater_operations",
                         "engaged_in_diving_operations", "engaged_in_military_operations",
                         "sailing", "pleasure"], 30):
    L_SHIP_TYPE[_k] = _n
for _k, _n in enumerate(["pilot_vessel", "sar", "tug", "port_tender", "anti_pollution",
                         "law_enforcement", "spare", "spare_2", "medical",
                         "ships_and_aircraft_of_states_not_parties_to_an_armed_conflict"], 50):
    L_SHIP_TYPE[_k] = _n
L_AIS_VERSION = ["itu_r_m1371_1", "itu_r_m1371_3", "itu_r_m1371_5", "itu_r_m1371_future"]
L_FIX_DEVICE = ["undefined", "gps", "glonass", "gps_glonass", "loran_c", "chayka",
                "integrated_navigation_system", "surveyed", "galileo"]
L_DTE = ["available", "unavailable"]
L_TRANSCEIVER = ["channel_a_vdl_reception", "channel_b_vdl_reception",
                 "channel_a_vdl_transmission", "channel_b_vdl_transmission",
                 "own_information_not_broadcast", "reserved_5"]

# AIS PGNs: the rows they share (the message header; the ship's dimensions at bit `at`, 0.1 m;
# the transceiver and sequence ID that end them, 3 reserved bits between)
AIS_HEAD = [("message_id", 0, 6, "lookup", L_AIS_MESSAGE),
            ("repeat_indicator", 6, 2, "lookup", L_REPEAT),
            ("user_id", 8, 32, U, "1")]


def ais_dimensions(at):
    names = ("length_m", "beam_m", "position_reference_from_starboard_m",
             "position_reference_from_bow_m")
    return [(n, at + 16 * i, 16, U, "0.1") for i, n in enumerate(names)]


def ais_end(at):
    return [("ais_transceiver_information", at, 5, "lookup", L_TRANSCEIVER),
            ("sequence_id", at + 8, 8, U, "1")]

L_PGN_LIST_FUNCTION = ["transmit", "receive"]
L_GROUP_FUNCTION = ["request", "command", "acknowledge", "read_fields", "read_fields_reply",
                    "write_fields", "write_fields_reply"]
L_PRIORITY_SETTING = [f"priority_{i}" for i in range(8)] + ["leave_unchanged", "reset_to_default"]
L_PGN_ERROR_CODE = ["acknowledge", "pgn_not_supported", "pgn_not_available", "access_denied",
                    "not_supported", "tag_not_supported", "read_or_write_not_supported"]
L_INTERVAL_ERROR_CODE = ["acknowledge", "not_supported_here", "interval_too_low",
                         "access_denied", "not_supported"]
L_PARAMETER_ERROR_CODE = ["acknowledge", "invalid_parameter_field", "temporary_error",
                          "parameter_out_of_range", "access_denied", "not_supported",
                          "read_or_write_not_supported"]
L_RANGE_RESIDUAL_MODE = ["used", "calculated_after"]
L_SATELLITE_STATUS = ["not_tracked", "tracked", "used", "not_tracked_diff", "tracked_diff",
                      "used_diff"]
L_GNSS_SYSTEM = ["gps", "glonass", "galileo", "beidou", "qzss"]
L_GNSS_TYPE = ["gps", "glonass", "gps_glonass", "gps_sbas", "gps_sbas_glonass", "chayka",
               "integrated", "surveyed", "galileo"]
L_GNSS_METHOD = ["no_gnss", "gnss_fix", "dgnss_fix", "precise_gnss", "rtk_fixed", "rtk_float",
                 "estimated", "manual", "simulated"]
L_GNSS_INTEGRITY = ["none", "safe", "caution", "unsafe"]

# lookups whose names sit in the sentinel range or depend on another field
L_MANUFACTURER = {code: snake(text) for code, text in MANUFACTURERS.items()}
L_DEVICE_CLASS = {0: "reserved_2000", 10: "system_tools", 20: "safety", 25: "internetwork",
                  30: "electrical_distribution", 35: "electrical_generation",
                  40: "steering_and_control_surfaces", 50: "propulsion", 60: "navigation",
                  70: "communication", 75: "sensor_communication_interface",
                  80: "instrumentation", 85: "external_environment", 90: "internal_environment",
                  100: "deck_cargo_fishing", 110: "human_interface", 120: "display",
                  125: "entertainment"}
L_INDUSTRY = ["global", "highway", "agriculture", "construction", "marine", "industrial"]
L_CONTROLLER_STATE = ["error_active", "error_passive", "bus_off"]
L_EQUIPMENT_STATUS = ["operational", "fault"]
L_GEAR = ["forward", "neutral", "reverse"]
L_STEERING_MODE = ["main_steering", "non_follow_up", "follow_up", "heading_control_standalone",
                   "heading_control", "track_control"]
L_TURN_MODE = ["rudder_limit_controlled", "turn_rate_controlled", "radius_controlled"]
F_TRANSMISSION_STATUS = ["check_transmission", "over_temperature", "low_oil_pressure",
                         "low_oil_level", "sail_drive"]
L_TIME_STAMP = {60: "unavailable", 61: "manual_input", 62: "dead_reckoning",
                63: "positioning_inoperative"}
L_NAV_STATUS = ["under_way_using_engine", "at_anchor", "not_under_command",
                "restricted_maneuverability", "constrained_by_draught", "moored", "aground",
                "engaged_in_fishing", "under_way_sailing", "hazardous_material_high_speed",
                "hazardous_material_wing_in_ground", "towing_astern",
                "pushing_ahead_or_towing_alongside", "", "ais_sart"]
L_SPECIAL_MANEUVER = ["unavailable", "not_engaged", "engaged", "reserved_3"]
# 129038 and 129039 share their first 184 bits: message, MMSI, position, course, speed, heading.
AIS_POSITION = [("message_id", 0, 6, "lookup", L_AIS_MESSAGE),
                ("repeat_indicator", 6, 2, "lookup", L_REPEAT),
                ("user_id", 8, 32, U, "1"),
                ("longitude_deg", 40, 32, S, "0.0000001"),
                ("latitude_deg", 72, 32, S, "0.0000001"),
                ("position_accuracy", 104, 1, "lookup", ["low", "high"]),
                ("raim", 105, 1, "lookup", ["not_in_use", "in_use"]),
                ("time_stamp", 106, 6, "lookup", L_TIME_STAMP),
                ("cog_rad", 112, 16, U, "0.0001"),
                ("sog_mps", 128, 16, U, "0.01"),
                ("communication_state", 144, 19, "u0", None),
                ("transceiver_information", 163, 5, "lookup", L_TRANSCEIVER),
                ("heading_rad", 168, 16, U, "0.0001")]

LAYOUT = {
    127488: [("instance", 0, 8, U, "1"),
             ("speed_rpm", 8, 16, U, "0.25"),
             ("boost_pressure_pa", 24, 16, U, "100"),
             ("tilt_trim_pct", 40, 8, S, "1")],
    127489: [("instance", 0, 8, U, "1"),
             ("oil_pressure_pa", 8, 16, U, "100"),
             ("oil_temperature_k", 24, 16, U, "0.1"),
             ("temperature_k", 40, 16, U, "0.01"),
             ("alternator_potential_v", 56, 16, S, "0.01"),
             ("fuel_rate_lph", 72, 16, S, "0.1"),
             ("total_engine_hours_s", 88, 32, U, "1"),
             ("coolant_pressure_pa", 120, 16, U, "100"),
             ("fuel_pressure_pa", 136, 16, U, "1000"),
             ("discrete_status_1", 160, 16, "flags", F_STATUS_1),
             ("discrete_status_2", 176, 16, "flags", F_STATUS_2),
             ("engine_load_pct", 192, 8, S, "1"),
             ("engine_torque_pct", 200, 8, S, "1")],
    128259: [("sid", 0, 8, U, "1"),
             ("speed_water_mps", 8, 16, U, "0.01"),
             ("speed_ground_mps", 24, 16, U, "0.01"),
             ("speed_type", 40, 8, "lookup", L_WATER),
             ("speed_direction", 48, 4, U, "1")],
    128275: [("date", 0, 16, "date", None),
             ("time", 16, 32, "time", None),
             ("log_m", 48, 32, U, "1"),
             ("trip_log_m", 80, 32, U, "1")],
    130311: [("sid", 0, 8, U, "1"),
             ("temperature_source", 8, 6, "lookup", L_TEMP),
             ("humidity_source", 14, 2, "lookup", L_HUM),
             ("temperature_k", 16, 16, U, "0.01"),
             ("humidity_pct", 32, 16, S, "0.004"),
             ("atmospheric_pressure_pa", 48, 16, U, "100")],
    130578: [("longitudinal_water_mps", 0, 16, S, "0.001"),
             ("transverse_water_mps", 16, 16, S, "0.001"),
             ("longitudinal_ground_mps", 32, 16, S, "0.001"),
             ("transverse_ground_mps", 48, 16, S, "0.001"),
             ("stern_water_mps", 64, 16, S, "0.001"),
             ("stern_ground_mps", 80, 16, S, "0.001")],
    # canboat's database: SID, heading (unsigned) and deviation, variation (signed) in 0.0001
    # rad, a 2-bit direction reference, 6 reserved bits.
    127250: [("sid", 0, 8, U, "1"),
             ("heading_rad", 8, 16, U, "0.0001"),
             ("deviation_rad", 24, 16, S, "0.0001"),
             ("variation_rad", 40, 16, S, "0.0001"),
             ("reference", 56, 2, "lookup", L_DIRECTION)],
    127251: [("sid", 0, 8, U, "1"),
             ("rate_radps", 8, 32, S, "3.125e-8")],
    127257: [("sid", 0, 8, U, "1"),
             ("yaw_rad", 8, 16, S, "0.0001"),
             ("pitch_rad", 24, 16, S, "0.0001"),
             ("roll_rad", 40, 16, S, "0.0001")],
    127258: [("sid", 0, 8, U, "1"),
             ("source", 8, 4, "lookup", L_VARIATION_SOURCE),
             ("age_of_service", 16, 16, "date", None),
             ("variation_rad", 32, 16, S, "0.0001")],
    128267: [("sid", 0, 8, U, "1"),
             ("depth_m", 8, 32, U, "0.01"),
             ("offset_m", 40, 16, S, "0.001"),
             ("range_m", 56, 8, U, "10")],
    129025: [("latitude_deg", 0, 32, S, "0.0000001"),
             ("longitude_deg", 32, 32, S, "0.0000001")],
    129026: [("sid", 0, 8, U, "1"),
             ("cog_reference", 8, 2, "lookup", L_DIRECTION),
             ("cog_rad", 16, 16, U, "0.0001"),
             ("sog_mps", 32, 16, U, "0.01")],
    127245: [("instance", 0, 8, U, "1"),
             ("direction_order", 8, 3, "lookup", L_RUDDER_DIRECTION),
             ("angle_order_rad", 16, 16, S, "0.0001"),
             ("position_rad", 32, 16, S, "0.0001")],
    130306: [("sid", 0, 8, U, "1"),
             ("wind_speed_mps", 8, 16, U, "0.01"),
             ("wind_angle_rad", 24, 16, U, "0.0001"),
             ("reference", 40, 3, "lookup", L_WIND_REFERENCE)],
    130312: [("sid", 0, 8, U, "1"),
             ("instance", 8, 8, U, "1"),
             ("source", 16, 8, "lookup", L_TEMP),
             ("actual_temperature_k", 24, 16, U, "0.01"),
             ("set_temperature_k", 40, 16, U, "0.01")],
    130313: [("sid", 0, 8, U, "1"),
             ("instance", 8, 8, U, "1"),
             ("source", 16, 8, "lookup", L_HUM),
             ("actual_humidity_pct", 24, 16, S, "0.004"),
             ("set_humidity_pct", 40, 16, S, "0.004")],
    130314: [("sid", 0, 8, U, "1"),
             ("instance", 8, 8, U, "1"),
             ("source", 16, 8, "lookup", L_PRESSURE_SOURCE),
             ("pressure_pa", 24, 32, S, "0.1")],
    130316: [("sid", 0, 8, U, "1"),
             ("instance", 8, 8, U, "1"),
             ("source", 16, 8, "lookup", L_TEMP),
             ("temperature_k", 24, 24, U, "0.001"),
             ("set_temperature_k", 48, 16, U, "0.1")],
    127508: [("instance", 0, 8, U, "1"),
             ("voltage_v", 8, 16, S, "0.01"),
             ("current_a", 24, 16, S, "0.1"),
             ("temperature_k", 40, 16, U, "0.01"),
             ("sid", 56, 8, U, "1")],
    127505: [("instance", 0, 4, U, "1"),
             ("fluid_type", 4, 4, "lookup", L_TANK_TYPE),
             ("level_pct", 8, 16, S, "0.004"),
             ("capacity_l", 24, 32, U, "0.1")],
    127506: [("sid", 0, 8, U, "1"),
             ("instance", 8, 8, U, "1"),
             ("dc_type", 16, 8, "lookup", L_DC_SOURCE),
             ("state_of_charge_pct", 24, 8, U, "1"),
             ("state_of_health_pct", 32, 8, U, "1"),
             ("time_remaining_s", 40, 16, U, "60"),
             ("ripple_voltage_v", 56, 16, U, "0.001"),
             ("remaining_capacity_ah", 72, 16, U, "1")],
    129283: [("sid", 0, 8, U, "1"),
             ("xte_mode", 8, 4, "lookup", L_RESIDUAL_MODE),
             ("navigation_terminated", 14, 2, "lookup", L_YES_NO),
             ("xte_m", 16, 32, S, "0.01")],
    126992: [("sid", 0, 8, U, "1"),
             ("source", 8, 4, "lookup", L_TIME_SOURCE),
             ("date", 16, 16, "date", None),
             ("time", 32, 32, "time", None)],
    129033: [("date", 0, 16, "date", None),
             ("time", 16, 32, "time", None),
             ("local_offset_s", 48, 16, S, "60")],
    129539: [("sid", 0, 8, U, "1"),
             ("desired_mode", 8, 3, "lookup", L_GNSS_MODE),
             ("actual_mode", 11, 3, "lookup", L_GNSS_MODE),
             ("hdop", 16, 16, S, "0.01"),
             ("vdop", 32, 16, S, "0.01"),
             ("tdop", 48, 16, S, "0.01")],
    129284: [("sid", 0, 8, U, "1"),
             ("distance_to_waypoint_m", 8, 32, U, "0.01"),
             ("course_bearing_reference", 40, 2, "lookup", L_DIRECTION),
             ("perpendicular_crossed", 42, 2, "lookup", L_YES_NO),
             ("arrival_circle_entered", 44, 2, "lookup", L_YES_NO),
             ("calculation_type", 46, 2, "lookup", L_BEARING_MODE),
             ("eta_time", 48, 32, "time", None),
             ("eta_date", 80, 16, "date", None),
             ("bearing_origin_to_destination_rad", 96, 16, U, "0.0001"),
             ("bearing_position_to_destination_rad", 112, 16, U, "0.0001"),
             ("origin_waypoint_number", 128, 32, U, "1"),
             ("destination_waypoint_number", 160, 32, U, "1"),
             ("destination_latitude_deg", 192, 32, S, "0.0000001"),
             ("destination_longitude_deg", 224, 32, S, "0.0000001"),
             ("waypoint_closing_velocity_mps", 256, 16, S, "0.01")],
    130577: [("data_mode", 0, 4, "lookup", L_RESIDUAL_MODE),
             ("cog_reference", 4, 2, "lookup", L_DIRECTION),
             ("sid", 8, 8, U, "1"),
             ("cog_rad", 16, 16, U, "0.0001"),
             ("sog_mps", 32, 16, U, "0.01"),
             ("heading_rad", 48, 16, U, "0.0001"),
             ("speed_water_mps", 64, 16, U, "0.01"),
             ("set_rad", 80, 16, U, "0.0001"),
             ("drift_mps", 96, 16, U, "0.01")],
    59904: [("requested_pgn", 0, 24, U, "1")],
    59392: [("control", 0, 8, "lookup", L_ISO_CONTROL),
             ("group_function", 8, 8, U, "1"),
             ("acknowledged_pgn", 40, 24, U, "1")],
    # lookups whose names sit in the sentinel range or depend on another field (canboat's
    # database; the ISO NAME is the 64 bits of 60928, bit 48 spare)
    60928: [("unique_number", 0, 21, U, "1"),
            ("manufacturer_code", 21, 11, "lookup", L_MANUFACTURER),
            ("device_instance_lower", 32, 3, "u0", None),
            ("device_instance_upper", 35, 5, "u0", None),
            ("device_function", 40, 8, "keyed", (49, 7, DEVICE_FUNCTIONS)),
            ("device_class", 49, 7, "lookup", L_DEVICE_CLASS),
            ("system_instance", 56, 4, U, "1"),
            ("industry_group", 60, 3, "lookup", L_INDUSTRY),
            ("arbitrary_address_capable", 63, 1, "lookup", L_YES_NO)],
    126993: [("data_transmit_offset_s", 0, 16, U, "0.001"),
             ("sequence_counter", 16, 8, U, "1"),
             ("controller_1_state", 24, 2, "lookup", L_CONTROLLER_STATE),
             ("controller_2_state", 26, 2, "lookup", L_CONTROLLER_STATE),
             ("equipment_status", 28, 2, "lookup", L_EQUIPMENT_STATUS)],
    127237: [("rudder_limit_exceeded", 0, 2, "lookup", L_YES_NO),
             ("off_heading_limit_exceeded", 2, 2, "lookup", L_YES_NO),
             ("off_track_limit_exceeded", 4, 2, "lookup", L_YES_NO),
             ("override", 6, 2, "lookup", L_YES_NO),
             ("steering_mode", 8, 3, "lookup", L_STEERING_MODE),
             ("turn_mode", 11, 3, "lookup", L_TURN_MODE),
             ("heading_reference", 14, 2, "lookup", L_DIRECTION),
             ("commanded_rudder_direction", 21, 3, "lookup", L_RUDDER_DIRECTION),
             ("commanded_rudder_angle_rad", 24, 16, S, "0.0001"),
             ("heading_to_steer_rad", 40, 16, U, "0.0001"),
             ("track_rad", 56, 16, U, "0.0001"),
             ("rudder_limit_rad", 72, 16, U, "0.0001"),
             ("off_heading_limit_rad", 88, 16, U, "0.0001"),
             ("radius_of_turn_order_m", 104, 16, S, "1"),
             ("rate_of_turn_order_radps", 120, 16, S, "0.00003125"),
             ("off_track_limit_m", 136, 16, S, "1"),
             ("vessel_heading_rad", 152, 16, U, "0.0001")],
    127252: [("sid", 0, 8, U, "1"),
             ("heave_m", 8, 16, S, "0.01")],
    127493: [("instance", 0, 8, U, "1"),
             ("transmission_gear", 8, 2, "lookup", L_GEAR),
             ("oil_pressure_pa", 16, 16, U, "100"),
             ("oil_temperature_k", 32, 16, U, "0.1"),
             ("discrete_status_1", 48, 8, "flags", F_TRANSMISSION_STATUS)],
    129038: AIS_POSITION + [("rate_of_turn_radps", 184, 16, S, "0.00003125"),
                            ("nav_status", 200, 4, "lookup", L_NAV_STATUS),
                            ("special_maneuver", 204, 2, "lookup", L_SPECIAL_MANEUVER),
                            ("sid", 216, 8, U, "1")],
    129039: AIS_POSITION + [("unit_type", 194, 1, "lookup", ["sotdma", "cs"]),
                            ("integrated_display", 195, 1, "lookup", L_YES_NO),
                            ("dsc", 196, 1, "lookup", L_YES_NO),
                            ("band", 197, 1, "lookup", ["top_525_khz", "entire_marine_band"]),
                            ("can_handle_msg_22", 198, 1, "lookup", L_YES_NO),
                            ("ais_mode", 199, 1, "lookup", ["autonomous", "assigned"]),
                            ("ais_communication_state", 200, 1, "lookup", ["sotdma", "itdma"]),
                            ("sid", 208, 8, U, "1")],
    # ---- strings: "text" = a fixed string of width / 8 bytes; "lau" = a counted string, at
    # the bit where the row before it ended (offset and width None).
    126996: [("nmea2000_version", 0, 16, U, "0.001"),
             ("product_code", 16, 16, U, "1"),
             ("model_id", 32, 256, "text", None),
             ("software_version_code", 288, 256, "text", None),
             ("model_version", 544, 256, "text", None),
             ("model_serial_code", 800, 256, "text", None),
             ("certification_level", 1056, 8, "lookup", L_CERTIFICATION),
             ("load_equivalency", 1064, 8, U, "1")],
    126998: [("installation_description_1", None, None, "lau", None),
             ("installation_description_2", None, None, "lau", None),
             ("manufacturer_information", None, None, "lau", None)],
    129794: AIS_HEAD + [("imo_number", 40, 32, U, "1"),
                        ("callsign", 72, 56, "text", None),
                        ("name", 128, 160, "text", None),
                        ("type_of_ship", 288, 8, "lookup", L_SHIP_TYPE)]
            + ais_dimensions(296) + [("eta_date", 360, 16, "date", None),
                                     ("eta_time", 376, 32, "time", None),
                                     ("draft_m", 408, 16, U, "0.01"),
                                     ("destination", 424, 160, "text", None),
                                     ("ais_version_indicator", 584, 2, "lookup", L_AIS_VERSION),
                                     ("gnss_type", 586, 4, "lookup", L_FIX_DEVICE),
                                     ("dte", 590, 1, "lookup", L_DTE)] + ais_end(592),
    129809: AIS_HEAD + [("name", 40, 160, "text", None)] + ais_end(200),
    129810: AIS_HEAD + [("type_of_ship", 40, 8, "lookup", L_SHIP_TYPE),
                        ("vendor_id", 48, 56, "text", None),
                        ("callsign", 104, 56, "text", None)]
            + ais_dimensions(160) + [("mothership_user_id", 224, 32, U, "1"),
                                     ("gnss_type", 260, 4, "lookup", L_FIX_DEVICE)] + ais_end(264),
    # A repeating group: (name, offset, bits of one repetition, "group", (the count field's
    # name or None for "to the end of the payload", the repetition's fields from its start)).
    126464: [("function_code", 0, 8, "lookup", L_PGN_LIST_FUNCTION),
             ("pgns", 8, 24, "group", (None, [("pgn", 0, 24, U, "1")]))],
    129540: [("sid", 0, 8, U, "1"),
             ("range_residual_mode", 8, 2, "lookup", L_RANGE_RESIDUAL_MODE),
             ("sats_in_view", 16, 8, U, "1"),
             ("satellites", 24, 96, "group", ("sats_in_view", [
                 ("prn", 0, 8, U, "1"),
                 ("elevation_rad", 8, 16, S, "0.0001"),
                 ("azimuth_rad", 24, 16, U, "0.0001"),
                 ("snr_db", 40, 16, S, "0.01"),
                 ("range_residuals_m", 56, 32, S, "0.00001"),
                 ("status", 88, 4, "lookup", L_SATELLITE_STATUS),
                 ("gnss_system", 92, 4, "lookup", L_GNSS_SYSTEM)]))],
    129029: [("sid", 0, 8, U, "1"),
             ("date", 8, 16, "date", None),
             ("time", 24, 32, "time", None),
             ("latitude_deg", 56, 64, S, "1e-16"),
             ("longitude_deg", 120, 64, S, "1e-16"),
             ("altitude_m", 184, 64, S, "1e-6"),
             ("gnss_type", 248, 4, "lookup", L_GNSS_TYPE),
             ("method", 252, 4, "lookup", L_GNSS_METHOD),
             ("integrity", 256, 2, "lookup", L_GNSS_INTEGRITY),
             ("number_of_svs", 264, 8, U, "1"),
             ("hdop", 272, 16, S, "0.01"),
             ("pdop", 288, 16, S, "0.01"),
             ("geoidal_separation_m", 304, 32, S, "0.01"),
             ("reference_stations", 336, 8, U, "1"),
             ("stations", 344, 32, "group", ("reference_stations", [
                 ("station_type", 0, 4, "lookup", L_GNSS_TYPE),
                 ("station_id", 4, 12, U, "1"),
                 ("age_of_corrections_s", 16, 16, U, "0.01")]))],
}
MAX_PAYLOAD = 223  # a fast packet's most bytes: a group's capacity follows from it


# A PGN whose layout its first byte picks (126208's function code), per code; a code not here
# has no layout: the payload is raw. "bytes": the payload from the offset on, as hex.
LAYOUT_BY_CODE = {
    126208: {
        0: [("function_code", 0, 8, "lookup", L_GROUP_FUNCTION), ("pgn", 8, 24, U, "1"),
            ("transmission_interval_s", 32, 32, U, "0.001"),
            ("transmission_interval_offset_s", 64, 16, U, "0.01"),
            ("number_of_parameters", 80, 8, U, "1"), ("parameters", 88, 0, "bytes", None)],
        1: [("function_code", 0, 8, "lookup", L_GROUP_FUNCTION), ("pgn", 8, 24, U, "1"),
            ("priority", 32, 4, "lookup", L_PRIORITY_SETTING),
            ("number_of_parameters", 40, 8, U, "1"), ("parameters", 48, 0, "bytes", None)],
        2: [("function_code", 0, 8, "lookup", L_GROUP_FUNCTION), ("pgn", 8, 24, U, "1"),
            ("pgn_error_code", 32, 4, "lookup", L_PGN_ERROR_CODE),
            ("transmission_interval_priority_error_code", 36, 4, "lookup", L_INTERVAL_ERROR_CODE),
            ("number_of_parameters", 40, 8, U, "1"),
            ("parameters", 48, 4, "group", ("number_of_parameters", [
                ("parameter", 0, 4, "lookup", L_PARAMETER_ERROR_CODE)]))],
    },
}


def layout_of(pgn, data):
    """The layout of a message of `pgn` with payload `data`; None: no layout (raw)."""
    if pgn in LAYOUT_BY_CODE:
        return LAYOUT_BY_CODE[pgn].get(data[0]) if data else None
    return LAYOUT.get(pgn)


def group_value(data, layout, offset, item_bits, arg):
    """A repeating group, by the rule of docs/nmea2000.md: as many repetitions as the count field
    says, or to the end of the payload (without a count field, or when the count is a sentinel);
    never more than the payload starts nor than 223 bytes hold after the fixed fields; a
    repetition cut short has its fields that are not held in full as null."""
    count_name, items = arg
    started = -(-max(0, len(data) * 8 - offset) // item_bits)
    n = min(started, (MAX_PAYLOAD * 8 - offset) // item_bits)
    if count_name is not None:
        _, c_offset, c_width, _, _ = next(f for f in layout if f[0] == count_name)
        count = (bits(data, c_offset, c_width) if c_offset + c_width <= len(data) * 8 else None)
        if count is not None and not sentinel(count, c_width, False):
            n = min(n, count)
    out = []
    for i in range(n):
        base = offset + i * item_bits
        out.append({name: field_value(data, base + o, w, k, a) for name, o, w, k, a in items})
    return out


# Strings (canboat's STRING_FIX and STRING_LAU), from the byte layouts: the text is the bytes
# before the first 0x00 or 0xFF, less its trailing padding (0xFF, 0x00, '@', whitespace); a byte
# is the character of its value (Latin-1); an empty text is null. A counted string: a length byte
# (counting itself and the next), an encoding byte (0 = UTF-16LE, else one byte a character),
# the bytes; a length past the payload takes what there is; a length below 2 ends the message
# (that field and the rest null).
STRING_PADDING = {0xFF, 0x00, ord("@"), ord(" "), 9, 10, 11, 12, 13}


def single_byte_text(raw):
    end = len(raw)
    for i, b in enumerate(raw):
        if b in (0x00, 0xFF):
            end = i
            break
    while end > 0 and raw[end - 1] in STRING_PADDING:
        end -= 1
    return raw[:end].decode("latin-1") or None


def utf16_text(raw):
    units = [raw[i] | raw[i + 1] << 8 for i in range(0, len(raw) - 1, 2)]
    end = len(units)
    for i, u in enumerate(units):
        if u in (0x0000, 0xFFFF):
            end = i
            break
    while end > 0 and units[end - 1] in STRING_PADDING - {0xFF}:
        end -= 1
    data = b"".join(u.to_bytes(2, "little") for u in units[:end])
    return data.decode("utf-16-le", "surrogatepass") or None


def string_rows(data, layout):
    """{name: expected} for the string rows of `layout`, the counted ones at running offsets."""
    out, at, stop = {}, 0, False
    for name, offset, width, kind, _ in layout:
        if kind == "text":
            start = offset // 8
            out[name] = single_byte_text(data[start:start + width // 8]) if start < len(data) else None
        elif kind == "lau":
            if stop or at >= len(data) or data[at] < 2 or len(data) - at < 2:
                stop = stop or at < len(data)
                out[name] = None
                continue
            taken = min(data[at], len(data) - at)
            body = data[at + 2:at + taken]
            out[name] = utf16_text(body) if data[at + 1] == 0 else single_byte_text(body)
            at += taken
    return out


def bits(data, offset, width):
    """Bit `offset` is bit offset % 8 of byte offset / 8, LSB first; fields little-endian."""
    return (int.from_bytes(data, "little") >> offset) & ((1 << width) - 1)


def sentinel(raw, width, signed):
    """N2K.md section 1: the top of the range. Unsigned: all ones = n/a, -1 = out of range
    (4 bits and more), -2 = reserved (8 bits and more). Signed (all 8 bits or more here): the
    largest positive value = n/a, -1 out of range, -2 reserved. Else None (a plain value)."""
    top = (1 << (width - 1)) - 1 if signed else (1 << width) - 1
    if raw == top:
        return "n/a"
    if raw == top - 1 and (signed or width >= 4):
        return "out_of_range"
    if raw == top - 2 and (signed or width >= 8):
        return "reserved"
    return None


def field_value(data, offset, width, kind, arg):
    if kind == "bytes":
        return data[offset // 8:].hex().upper()
    if offset + width > len(data) * 8:
        return None  # not sent (a short payload)
    raw = bits(data, offset, width)
    if kind == "flags":  # no sentinel: every bit is a flag
        return [arg[b] if b < len(arg) else f"bit_{b}" for b in range(width) if raw >> b & 1]
    signed = kind == S
    if signed and raw >> (width - 1):
        raw -= 1 << width
    if kind == "lookup" and isinstance(arg, dict):  # names of some values only
        if arg.get(raw):
            return arg[raw]
        kind, arg = "lookup", []
    if kind == "lookup" and raw < len(arg) and arg[raw]:
        return arg[raw]  # a named raw value is a value, even among the top (sentinel) values
    if kind == "u0":  # every raw value a value: no sentinel
        return Decimal(raw)
    if kind == "keyed":  # named by (key field's raw value, raw value); unnamed pairs as numbers
        key_offset, key_width, table = arg
        key = bits(data, key_offset, key_width) if key_offset + key_width <= len(data) * 8 else None
        if raw <= (1 << width) - 4 and (key, raw) in table:
            return snake(table[(key, raw)])
        kind, arg = "lookup", []
    if kind == "lookup":
        # canboat's rule for an unnamed lookup value: the top three of more than 2 bits, the top
        # two of 2 bits (J1939's error / not available) are no values
        top = (1 << width) - 1
        names = {top: "n/a", top - 1: "out_of_range", top - 2: "reserved"}
        special = names.get(raw) if raw > top - (3 if width > 2 else 2) else None
    else:
        special = sentinel(raw, width, signed)
    if special:
        return None if special == "n/a" else special
    if kind in (U, S):
        return raw * Decimal(arg)
    if kind == "lookup":
        return arg[raw] if raw < len(arg) and arg[raw] else raw  # "": a value with no name
    if kind == "date":
        return (datetime.date(1970, 1, 1) + datetime.timedelta(days=raw)).isoformat()
    if kind == "time":
        s, frac = divmod(raw, 10000)
        return f"{s // 3600:02d}:{s // 60 % 60:02d}:{s % 60:02d}.{frac:04d}"
    raise ValueError(kind)


# Edge values not in the vectors, run through both decoders in the layout case: every sentinel
# of every field width, the largest plain values, unnamed lookup values and flag bits (129029's
# integrity 2 and 3: Caution and Unsafe, as analyzer names them).
LAYOUT_EXTRA = b"""\
2024-07-03T15:42:58.000Z,2,128259,35,255,8,fd,fd,ff,fc,ff,fd,fd,ff
2024-07-03T15:42:58.000Z,2,128259,35,255,8,fc,fc,ff,00,80,07,0d,ff
2024-07-03T15:42:58.000Z,2,128259,35,255,8,fe,fc,ff,fe,ff,04,0e,ff
2024-07-03T15:42:58.000Z,2,127488,35,255,8,fd,fd,ff,fc,ff,7d,ff,ff
2024-07-03T15:42:58.000Z,2,127488,35,255,8,fe,fd,ff,fc,ff,81,ff,ff
2024-07-03T15:42:58.000Z,5,130311,35,255,8,fe,be,fd,ff,fd,7f,fd,ff
2024-07-03T15:42:58.000Z,5,130311,35,255,8,fd,bd,00,00,00,80,00,00
2024-07-03T15:42:58.000Z,5,130311,35,255,8,fc,50,fc,ff,fc,7f,fc,ff
2024-07-03T15:42:58.000Z,5,130311,35,255,8,00,0f,01,00,01,00,01,00
2024-07-03T15:42:58.000Z,2,127489,35,255,26,fd,fd,ff,fd,ff,fd,ff,fd,7f,fd,7f,fd,ff,ff,ff,fd,ff,fd,ff,00,ff,ff,ff,ff,7d,80
2024-07-03T15:42:58.000Z,2,127489,35,255,26,fe,fe,ff,fe,ff,fe,ff,fe,7f,fe,7f,fe,ff,ff,ff,fe,ff,fe,ff,ff,00,00,00,ff,7e,7e
2024-07-03T15:42:58.000Z,2,127489,35,255,26,fc,fc,ff,fc,ff,fc,ff,01,80,fc,7f,fc,ff,ff,ff,fc,ff,fc,ff,ff,01,80,81,00,7c,81
2024-07-03T15:42:58.000Z,6,128275,35,255,14,fd,ff,fd,ff,ff,ff,00,00,00,00,fc,ff,ff,ff
2024-07-03T15:42:58.000Z,6,128275,35,255,14,fc,ff,10,5c,26,05,01,00,00,00,fc,ff,ff,ff
2024-07-03T15:42:58.000Z,6,128275,35,255,14,00,00,00,00,00,00,fe,ff,ff,ff,00,00,00,00
2024-07-03T15:42:58.000Z,2,130578,35,255,12,fd,7f,fc,7f,00,80,01,80,fe,7f,00,00
2024-07-03T15:42:58.000Z,2,127251,35,255,8,00,fd,ff,ff,7f,ff,ff,ff
2024-07-03T15:42:58.000Z,2,130306,35,255,8,fd,fd,ff,fe,ff,fd,ff,ff
2024-07-03T15:42:58.000Z,2,130306,35,255,8,fe,00,00,fc,ff,fe,ff,ff
2024-07-03T15:42:58.000Z,6,127505,35,255,8,de,fd,7f,fd,ff,ff,ff,ff
2024-07-03T15:42:58.000Z,6,127505,35,255,8,0c,00,80,fc,ff,ff,ff,ff
2024-07-03T15:42:58.000Z,5,130316,35,255,8,fd,fd,fd,fd,ff,ff,fd,ff
2024-07-03T15:42:58.000Z,6,129539,35,255,8,00,f5,00,80,fe,7f,fd,7f
2024-07-03T15:42:58.000Z,3,129283,35,255,8,01,b4,00,00,00,80,ff,ff
2024-07-03T15:42:58.000Z,3,129033,35,255,8,fe,ff,ff,ff,ff,ff,00,80
2024-07-03T15:42:58.000Z,3,126992,35,255,8,01,f0,00,70,00,00,00,00
2024-07-03T15:42:58.000Z,6,126996,40,255,134,34,08,01,00,43,61,66,e9,20,01,7f,80,fe,21,ff,ff,ff,ff,ff,ff,ff,ff,ff,ff,ff,ff,ff,ff,ff,ff,ff,ff,ff,ff,ff,ff,41,42,ff,43,44,20,20,20,20,20,20,20,20,20,20,20,20,20,20,20,20,20,20,20,20,20,20,20,20,20,20,20,09,40,20,00,00,00,00,00,00,00,00,00,00,00,00,00,00,00,00,00,00,00,00,00,00,00,00,00,00,00,00,00,71,22,5c,2f,40,40,40,40,40,40,40,40,40,40,40,40,40,40,40,40,40,40,40,40,40,40,40,40,40,40,40,40,01,02
2024-07-03T15:42:58.000Z,6,126998,40,255,23,0d,00,48,00,e9,00,ac,20,3d,d8,00,de,41,06,00,00,d8,41,00,04,01,e9,7f
2024-07-03T15:42:58.000Z,6,126998,40,255,9,01,01,41,42,05,01,43,44,45
2024-07-03T15:42:58.000Z,6,126998,40,255,14,0a,00,61,00,62,00,20,00,40,00,03,01,7a,09
2024-07-03T15:42:58.000Z,6,129809,40,255,7,18,47,38,8c,0e,c4,d6
2024-07-03T15:42:58.000Z,3,129029,52,255,43,ff,84,50,90,ed,fb,03,c0,f2,28,38,52,24,f4,02,00,66,c0,75,30,4b,18,ea,d7,8a,43,01,00,00,00,00,24,fe,1a,32,00,46,00,4a,01,00,00,00
2024-07-03T15:42:58.000Z,3,129029,52,255,43,ff,84,50,90,ed,fb,03,c0,f2,28,38,52,24,f4,02,00,66,c0,75,30,4b,18,ea,d7,8a,43,01,00,00,00,00,24,ff,1a,32,00,46,00,4a,01,00,00,00
"""


def compare_layout(where, ours, want):
    """ours: seawire-decode's JSON object; want: a message decoded here."""
    global compared
    pgn = want["pgn"]
    check(ours.get("type") == f"PGN{pgn}", f"{where}: type {ours.get('type')!r}, PGN {pgn}")
    for k in ("prio", "src", "dst"):
        compared += 1
        check(ours.get(k) == want[k], f"{where}: {k} {ours.get(k)!r}, expected {want[k]!r}")
    for k, v in want["extra"].items():
        compared += 1
        check(ours.get(k) == v, f"{where}: {k} {ours.get(k)!r}, expected {v!r}")
    if want["time"] is None:
        check("time_s" not in ours, f"{where}: time_s {ours.get('time_s')} without a log time")
    else:
        compared += 1
        # The log's time to the microsecond (seawire keeps microseconds; canboat lines may
        # carry nanoseconds).
        got = ours.get("time_s")
        check(is_number(got) and abs(Decimal(got) - want["time"]) < Decimal("0.000001"),
              f"{where}: time_s {got}, expected {want['time']}")
    layout = layout_of(pgn, want["data"])
    if layout is None:
        # A PGN (or layout) seawire does not describe: its whole payload, as assembled here.
        compared += 1
        check(set(ours) - META == {"data"} and ours["data"] == want["data"].hex().upper(),
              f"{where}: {ours.get('data')!r} ({sorted(set(ours) - META)}), assembled here "
              f"{want['data'].hex().upper()}")
        return
    names = {f[0] for f in layout}
    check(set(ours) - META == names, f"{where}: fields {sorted(set(ours) - META)}, "
          f"expected {sorted(names)}")
    def same_value(got, expected):
        if is_number(expected):
            return is_number(got) and Decimal(got) == expected
        return got == expected

    strings = string_rows(want["data"], layout)
    for name, offset, width, kind, arg in layout:
        compared += 1
        got = ours.get(name, "<missing>")
        if kind == "group":
            expected = group_value(want["data"], layout, offset, width, arg)
            ok = (isinstance(got, list) and len(got) == len(expected) and
                  all(isinstance(g, dict) and set(g) == set(e) and
                      all(same_value(g[k], e[k]) for k in e) for g, e in zip(got, expected)))
        else:
            expected = (strings[name] if name in strings
                        else field_value(want["data"], offset, width, kind, arg))
            ok = same_value(got, expected)
        check(ok, f"{where}: {name} = {got!r}, expected {expected!r} "
              f"(bits {offset}+{width} of {want['data'].hex()})")


def case_layout():
    inputs = [(os.path.basename(p), open(p, "rb").read()) for p in vectors()]
    inputs.append(("edge values", LAYOUT_EXTRA))
    for name, data in inputs:
        lines = [l for l in data.decode().splitlines() if l.strip()]
        want = [m for m in messages(lines)
                if m["pgn"] in LAYOUT or m["pgn"] in LAYOUT_BY_CODE
                or m["pgn"] not in CANBOAT_FIELDS]
        p = run([], data, 0)
        ours = [exact(l) for l in p.stdout.decode().splitlines()]
        check(len(ours) == len(want),
              f"{name}: {len(ours)} messages from seawire-decode, {len(want)} from the layout")
        for i, (o, w) in enumerate(zip(ours, want)):
            compare_layout(f"{name} message {i + 1}", o, w)


# ---------------------------------------------------------------------------------------------

def canboat_time(where, fmt, ours, stamp, offsets):
    """Compares our time_s with canboat's "timestamp"; False when they cannot be related."""
    global compared
    got = ours.get("time_s")
    theirs, _ = iso_seconds(stamp)
    if fmt == "actisense_n2k_ascii":
        # The time of day only, which canboat prints as it is ("00:00:57.086").
        h, m, sec = stamp.split(":")
        theirs = int(h) * 3600 + int(m) * 60 + Decimal(sec)
    elif fmt == "yd_raw":
        # YD RAW has the time of day only: seawire gives seconds since midnight; canboat
        # prefixes the date it ran on (2026-11-21 in these files), so only the time of day
        # relates.
        theirs %= 86400
    elif fmt == "canboat" and offsets.get(stamp[:23]):
        # The input named a zone offset (…-07:00): canboat printed the local clock digits with
        # a "Z" and dropped the offset, so its timestamp is not the instant the line names.
        # The layout case checks time_s against the input's own timestamp instead.
        return False
    elif fmt not in ("canboat", "candump_log"):
        return False  # candump's default format carries no time
    # Otherwise canboat's timestamp is the log's instant (canboat lines as written; candump -L
    # seconds converted to UTC) rounded to the millisecond.
    compared += 1
    check(is_number(got) and abs(Decimal(got) - theirs) <= Decimal("0.0005"),
          f"{where}: time_s {got} vs canboat {stamp}: not the same instant to the millisecond")
    return True


def compare_raw(where, ours, theirs):
    """A PGN seawire does not describe: one message with its whole payload as "data". Where
    canboat knows no more of it than a manufacturer's proprietary message, it shows the bytes
    after the manufacturer and industry codes (the first two): ours from the third on."""
    global compared
    check(set(ours) - META == {"data"}, f"{where}: fields {sorted(set(ours) - META)} of a PGN "
          "seawire does not describe")
    fields = theirs.get("fields", {})
    if "data" in fields and set(fields) <= {"manufacturerCode", "industryCode", "data"}:
        compared += 1
        check(ours["data"][4:] == fields["data"].replace(" ", ""),
              f"{where}: data {ours['data']} vs canboat's {fields['data']} after two bytes")


def case_canboat():
    global compared
    skipped_times = 0
    for path in vectors():
        name = os.path.basename(path)
        with open(path) as f:
            lines = [l.rstrip("\r\n") for l in f if l.strip()]
        formats = {line_format(l) for l in lines} - {"comment"}
        check(len(formats) == 1, f"{name}: mixed log formats {formats}")
        fmt = formats.pop()
        # canboat lines by timestamp (to the millisecond, "T" separator): named a zone offset?
        offsets = {}
        if fmt == "canboat":
            for l in lines:
                if l.startswith("#"):
                    continue
                ts = l.split(",")[0]
                key = ts[:10] + "T" + ts[11:23]
                offsets[key] = iso_seconds(ts)[1]
        ours = decode_file(path)
        with open(path[:-3] + ".out.json") as f:
            theirs = [next(iter(exact(l).values())) for l in f if l.strip()]
        # canboat decodes a gateway's own messages (pseudo-PGNs); seawire skips them.
        theirs = [t for t in theirs if t["pgn"] not in PSEUDO_PGNS]
        check(len(ours) == len(theirs),
              f"{name}: {len(ours)} messages, canboat {len(theirs)}")
        for i, (o, t) in enumerate(zip(ours, theirs)):
            where = f"{name} message {i + 1} (PGN {t['pgn']})"
            compared += 1
            check(o.get("type") == f"PGN{t['pgn']}", f"{where}: type {o.get('type')!r}")
            for k in ("src", "dst", "prio"):
                compared += 1
                check(o.get(k) == t[k], f"{where}: {k} {o.get(k)!r}, canboat {t[k]!r}")
            if not canboat_time(where, fmt, o, t["timestamp"], offsets):
                skipped_times += 1
            if t["pgn"] not in CANBOAT_FIELDS and "data" in o:
                compare_raw(where, o, t)
                continue
            table = CANBOAT_FIELDS.get(t["pgn"])
            if t["pgn"] in CANBOAT_FIELDS_BY_CODE:
                # the layout the function code picks; a code seawire has none for: raw
                code = L_GROUP_FUNCTION.index(o["function_code"]) if "function_code" in o else None
                table = CANBOAT_FIELDS_BY_CODE[t["pgn"]].get(code)
                if table is None:
                    compared += 1
                    check(set(o) - META == {"data"}, f"{where}: a layout seawire does not "
                          f"describe, fields {sorted(set(o) - META)}")
                    continue
            if not check(table is not None, f"{where}: no mapping for this PGN"):
                continue
            check(set(o) - META == set(table),
                  f"{where}: our fields {sorted(set(o) - META)} vs mapping {sorted(table)}")
            fields = t.get("fields", {})  # none at all for a frame of no data
            unmapped = ({f for f in fields if not CANBOAT_IGNORED.fullmatch(f)}
                        - {c for c, _ in table.values()})
            check(not unmapped, f"{where}: canboat fields not in the mapping: {sorted(unmapped)}")
            for ours_name, (their_name, cmp) in table.items():
                compared += 1
                if their_name == "list" and their_name not in fields and o.get(ours_name) in ([], ""):
                    continue  # canboat has no "list" for a group of no repetitions (no bytes)
                if their_name not in fields:
                    # canboat leaves out a field a short message did not send; seawire gives null
                    check(o.get(ours_name, "<missing>") is None,
                          f"{where}: canboat has no {their_name} (not sent), ours "
                          f"{o.get(ours_name, '<missing>')!r}")
                    continue
                a, b = o.get(ours_name, "<missing>"), fields[their_name]
                why = cmp(a, b)
                check(why is None, f"{where}: {ours_name} = {json.dumps(a, default=str)} vs "
                      f"canboat {their_name} = {json.dumps(b, default=str)}: {why}")
    print(f"canboat: time comparison skipped for {skipped_times} message(s) whose input named "
          f"a zone offset (canboat drops it)")


# ---------------------------------------------------------------------------------------------

def case_errors():
    good_128259 = "(1502984866.953084) slcan0 09F50374#001200FFFF00FFFF"
    lines = [
        good_128259,                                                            # 1
        "(1502984866.960000) slcan0 09F50374#0012ZZFFFF00FFFF",                 # 2 bad hex
        "(1502984866.970000) slcan0 09F50374#001200FFFF00FFFF00",               # 3 9 bytes
        "(1502984866.980000) slcan0 123#001200FFFF00FFFF",                      # 4 11-bit id
        "this is no CAN log line",                                              # 5
        "2016-04-09T16:41:40.049Z,2,127488,16,255,8,00,7a,0c,ff,ff,7f,ff,ff",   # 6
        "(1502984867.285145) slcan0 19F51374#C00EFFFFFFFFFFFF",                 # 7 frame 0
        "(1502984867.285163) slcan0 19F51374#C200FFFFFFFFFFFF",                 # 8 frame 2
        "21:55:35.425 R 15FD0723 FF C0 D9 6F FF 7F FF FF",                      # 9
        "(15029848x7.895302) slcan0 09F50374#001200FFFF00FFFF",                 # 10 bad time
        "2016-04-09T16:41:40.049Z,2,127488,16,255,8,00,7a,0c,ff,ff,7f,ff",      # 11 7 of 8
        "(1720021378.000000) can0 19F51323#000EC34D201EB921",                   # 12
        "(1720021378.000000) can0 19F51323#0140E20100D21E00",                   # 13
        "(1720021378.000000) can0 19F51323#0200FFFFFFFFFFFF",                   # 14
        "(1502984868.000000) slcan0 09F50374#001500FFFF01FFFF",                 # 15
    ]
    bad = {2: "bad_number", 3: "bad_length", 4: "bad_can_id", 5: "bad_log_line",
           10: "bad_time", 11: "bad_length"}
    good = [(1, "PGN128259", {"src": 116, "speed_water_mps": Decimal("0.18"),
                              "speed_type": "paddle_wheel"}),
            (6, "PGN127488", {"src": 16, "speed_rpm": Decimal("798.5")}),
            (9, "PGN130311", {"src": 35, "temperature_k": Decimal("286.33"),
                              "temperature_source": "sea"}),
            (14, "PGN128275", {"src": 35, "log_m": 123456, "trip_log_m": 7890,
                               "date": "2024-07-03", "time": "15:42:58.0000"}),
            (15, "PGN128259", {"src": 116, "speed_water_mps": Decimal("0.21"),
                               "speed_type": "pitot_tube"})]
    data = "\n".join(lines).encode() + b"\n"

    for args in ([], ["--input", "n2k"]):
        p = run(args, data, 1)
        out = [exact(l) for l in p.stdout.decode().splitlines()]
        # In input order: an error object for each bad line, a message for each good one (the
        # fast packet of lines 7-8 lacks frame 1 and gives nothing).
        want = sorted([(n, "error") for n in bad] + [(n, "message") for n, _, _ in good])
        got = [("error" if "error" in o else "message") for o in out]
        check(got == [k for _, k in want], f"{args}: output sequence {got}, expected {want}")
        errors = [o for o in out if "error" in o]
        for o, n in zip(errors, sorted(bad)):
            check(o.get("line") == n and o.get("error") == bad[n],
                  f"{args}: error {o}, expected line {n} {bad[n]}")
            check(isinstance(o.get("field"), int) and o["field"] >= 0,
                  f"{args}: error for line {n} without a field number: {o}")
            check(o.get("input") == lines[n - 1], f"{args}: line {n} input {o.get('input')!r}")
        msgs = [o for o in out if "error" not in o]
        for o, (n, t, values) in zip(msgs, good):
            check(o.get("type") == t, f"{args}: line {n}: {o}, expected {t}")
            for k, v in values.items():
                check(o.get(k) == v, f"{args}: line {n}: {k} = {o.get(k)!r}, expected {v!r}")

    # --stats: counts by error, and the fast packet dropped for its missing frame.
    p = run(["--format", "none", "--stats"], data, 1)
    err = p.stderr.decode()
    for name, n in (("bad_length", 2), ("bad_number", 1), ("bad_can_id", 1),
                    ("bad_log_line", 1), ("bad_time", 1), ("missing_frame", 1)):
        check(re.search(rf"\b{name}\s+{n}\b", err), f"--stats: no '{name} {n}' in {err!r}")
    check(p.stdout == b"", f"--format none wrote {p.stdout[:200]!r}")
    # A fast packet still unfinished at the end of the log is a missing_frame drop too.
    p = run(["--stats"], (good_128259 + "\n" + lines[6] + "\n").encode())
    check(re.search(r"\bmissing_frame\s+1\b", p.stderr.decode()),
          f"unfinished fast packet at the end: {p.stderr.decode()!r}")
    check(len(p.stdout.decode().splitlines()) == 1, f"unfinished fast packet: {p.stdout!r}")

    def one(args, text, want_rc):
        p = run(args, text.encode(), want_rc)
        return [exact(l) for l in p.stdout.decode().splitlines()]

    canboat = lines[5]
    yd = lines[8]
    candump = "can0  09F50323  [8]  FF 00 00 FF FF 00 FF FF"
    # --input n2k: a CAN log even when its first line is no CAN log line.
    out = one(["--input", "n2k"], f"{lines[4]}\n{good_128259}\n", 1)
    check([o.get("error") or o.get("type") for o in out] == ["bad_log_line", "PGN128259"]
          and out[0].get("line") == 1, f"--input n2k, garbage first: {out}")
    # --input nmea: the same CAN log is no NMEA, nothing decoded as a PGN.
    out = one(["--input", "nmea"], f"{good_128259}\n{canboat}\n", 1)
    check(not any(str(o.get("type", "")).startswith("PGN") for o in out),
          f"--input nmea decoded PGNs: {out}")
    # --log-format: every line in that format, the others errors. A line of another format is
    # reported as the first thing that does not fit: no "(" or no comma-separated fields is
    # bad_log_line; a YD RAW reader sees a bad time, a candump reader a bad identifier.
    for fmt, fits, other, names in (("candump_log", good_128259, canboat, {"bad_log_line"}),
                                    ("canboat", canboat, good_128259, {"bad_log_line"}),
                                    ("yd_raw", yd, canboat, {"bad_log_line", "bad_time"}),
                                    ("candump", candump, yd, {"bad_log_line", "bad_can_id"})):
        out = one(["--log-format", fmt], f"{other}\n{fits}\n{other}\n", 1)
        kinds = [o.get("error") or o.get("type") for o in out]
        check(len(out) == 3 and kinds[0] in names and kinds[2] in names
              and kinds[1].startswith("PGN") and [out[0].get("line"), out[2].get("line")] == [1, 3],
              f"--log-format {fmt}: {out}")
        out = one(["--log-format", fmt], f"{fits}\n", 0)
        check(len(out) == 1 and out[0].get("type", "").startswith("PGN"),
              f"--log-format {fmt}, its own line: {out}")
        # The same lines without --log-format: told apart line by line, all decoded.
        one(["--input", "n2k"], f"{other}\n{fits}\n{other}\n", 0)
    run(["--log-format", "actisense"], b"", 2)
    run(["--input", "can"], b"", 2)

    # canboat's header: honoured, not an error (exit 0 when every message decodes), recognised
    # as a CAN log by itself; a FAST line of 8 bytes is a whole message.
    fast8 = "2024-07-03T15:42:58.000Z,6,128275,35,255,8,c3,4d,20,1e,b9,21,ff,ff"
    out = one([], f"# format=FAST\n{fast8}\n", 0)
    check(len(out) == 1 and out[0].get("date") == "2024-07-03"
          and out[0].get("time") == "15:42:58.0000" and out[0].get("log_m") is None,
          f"# format=FAST, 8 bytes of 128275: {out}")
    # without the header, as the log's first canboat line: canboat reads it as one frame
    out = one([], f"{fast8}\n", 0)
    check(out == [], f"8 bytes of 128275 first in a log without header: a frame: {out}")
    # comments are skipped; headers naming formats seawire does not read are precise errors and
    # the lines after them still read
    out = one([], f"# written on board\n# format=AIRMAR\n# format=SEATALK\n{canboat}\n", 1)
    kinds = [o.get("error") or o.get("type") for o in out]
    check(kinds == ["unknown_log_format", "unknown_log_format", "PGN127488"]
          and [out[0].get("line"), out[1].get("line")] == [2, 3]
          and "canboat format seawire does not read" in out[0].get("detail", "")
          and "no canboat format has this name" in out[1].get("detail", ""),
          f"unknown format headers: {out}")
    # PLAIN: every line a frame; a longer line is refused, naming the length
    out = one([], f"# format=PLAIN\n{canboat}\n"
              "2016-04-09T16:41:39.628Z,2,127489,16,255,26,00,2f,06,ff,ff,e3,73,65,05,ff,7f,"
              "72,10,00,00,ff,ff,ff,ff,ff,06,00,00,00,7f,7f\n", 1)
    check([o.get("error") or o.get("type") for o in out] == ["PGN127488", "bad_length"]
          and "length" in out[1].get("detail", ""), f"# format=PLAIN, 26 bytes: {out}")
    # YDWG02: Yacht Devices RAW lines, the first one decides nothing else
    out = one([], f"# format=YDWG02\n{yd}\n{canboat}\n", 1)
    check([o.get("error") or o.get("type") for o in out] == ["PGN130311", "bad_time"],
          f"# format=YDWG02: {out}")
    # A frame of no data reads in every format (fields not available); a fast-packet PGN's
    # frame of no data is dropped as short (not a line error)
    for empty in ("21:55:35.925 R 09F50323", "(1502984866.953084) slcan0 09F50374#",
                  "can0  09F50323   [0]", "2024-07-03T15:42:58.000Z,2,128259,35,255,0"):
        out = one(["--input", "n2k"], f"{empty}\n", 0)
        check(len(out) == 1 and out[0].get("type") == "PGN128259"
              and out[0].get("speed_water_mps", 0) is None, f"frame of no data {empty!r}: {out}")
    p = run(["--stats", "--format", "none"], b"21:55:35.925 R 19F51323\n", 0)
    check(re.search(r"\bshort_frame\s+1\b", p.stderr.decode()), f"empty fast frame: {p.stderr!r}")
    # Frames 1 and 2 of a fast packet swapped, as some gateways deliver them: assembled
    swapped = ("(1720021378.000000) can0 19F51323#000EC34D201EB921\n"
               "(1720021378.000000) can0 19F51323#0200FFFFFFFFFFFF\n"
               "(1720021378.000000) can0 19F51323#0140E20100D21E00\n")
    out = one([], swapped, 0)
    check(len(out) == 1 and out[0].get("log_m") == 123456 and out[0].get("trip_log_m") == 7890,
          f"frames 1 and 2 swapped: {out}")
    # A fast packet longer than its PGN (fields appended by a newer sender): decoded from frames
    # as from a FAST line
    longer = ("(1720021378.000000) can0 09FE1223#4013C40988FF280A\n"
              "(1720021378.000000) can0 09FE1223#41D4FEFF7FFF7FFF\n"
              "(1720021378.000000) can0 09FE1223#42010203040506FF\n")
    a = one([], longer, 0)
    b = one([], "2024-07-03T15:42:58.000Z,2,130578,35,255,19,c4,09,88,ff,28,0a,d4,fe,ff,7f,ff,"
                "7f,ff,01,02,03,04,05,06\n", 0)
    strip = lambda o: {k: v for k, v in o.items() if k not in META}
    check(len(a) == 1 and len(b) == 1 and strip(a[0]) == strip(b[0])
          and a[0].get("longitudinal_water_mps") == Decimal("2.500"),
          f"130578 of 19 bytes, frames vs FAST line: {a} {b}")


harness.case_of(globals(), CASE)()
if compared:
    print(f"{CASE}: {compared} values compared")
harness.finish()
