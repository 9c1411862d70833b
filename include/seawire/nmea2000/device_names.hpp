// SPDX-License-Identifier: BSL-1.0
#pragma once
// The codes of an ISO NAME (60928 ISO Address Claim, nmea2000/pgns.hpp): manufacturers, industry
// groups, device classes, and the device functions, whose names depend on the device class. The
// values and texts are the NMEA 2000 and ISO 11783 registrations as canboat's database records
// them; the snake_case names are seawire's (JSON, CSV, fmt).

#include <array>
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "seawire/nmea2000/field.hpp"

namespace seawire::nmea2000 {

/// A manufacturer's registered code (11 bits). Only the values are declared: the codes are
/// named by lookup_names and lookup_titles.
enum class manufacturer_code : std::uint16_t {};

namespace detail {
struct code_name {
  std::uint16_t code;
  std::string_view name;
  std::string_view title;
};
inline constexpr std::array<code_name, 283> manufacturer_codes{{
    {69, "arks_enterprises", "ARKS Enterprises"},
    {78, "fw_murphy_enovation_controls", "FW Murphy/Enovation Controls"},
    {80, "twin_disc", "Twin Disc"},
    {85, "kohler_power_systems", "Kohler Power Systems"},
    {88, "hemisphere_gps", "Hemisphere GPS"},
    {135, "airmar", "Airmar"},
    {137, "maretron", "Maretron"},
    {140, "lowrance", "Lowrance"},
    {144, "mercury_marine", "Mercury Marine"},
    {147, "nautibus_electronic", "Nautibus Electronic"},
    {148, "blue_water_data", "Blue Water Data"},
    {154, "westerbeke", "Westerbeke"},
    {157, "isspro", "ISSPRO"},
    {161, "offshore_systems_uk", "Offshore Systems (UK)"},
    {163, "evinrude_brp", "Evinrude/BRP"},
    {165, "cpac_systems", "CPAC Systems"},
    {168, "xantrex_technology", "Xantrex Technology"},
    {169, "marlin_technologies", "Marlin Technologies"},
    {172, "yanmar_marine", "Yanmar Marine"},
    {174, "volvo_penta", "Volvo Penta"},
    {176, "carling_technologies_inc_moritz_aerospace",
     "Carling Technologies Inc. (Moritz Aerospace)"},
    {185, "beede_instruments", "Beede Instruments"},
    {192, "floscan_instrument", "Floscan Instrument"},
    {193, "nobeltec", "Nobeltec"},
    {198, "mystic_valley_communications", "Mystic Valley Communications"},
    {199, "actia", "Actia"},
    {201, "disenos_y_technologia", "Disenos Y Technologia"},
    {211, "digital_switching_systems", "Digital Switching Systems"},
    {215, "xintex_atena", "Xintex/Atena"},
    {224, "emmi_network", "EMMI NETWORK"},
    {228, "zf", "ZF"},
    {229, "garmin", "Garmin"},
    {233, "yacht_monitoring_solutions", "Yacht Monitoring Solutions"},
    {235, "sailormade_marine_telemetry_tetra_technology",
     "Sailormade Marine Telemetry/Tetra Technology"},
    {243, "eride", "Eride"},
    {257, "honda_motor", "Honda Motor"},
    {272, "groco", "Groco"},
    {273, "actisense", "Actisense"},
    {274, "amphenol_ltw_technology", "Amphenol LTW Technology"},
    {275, "navico", "Navico"},
    {283, "hamilton_jet", "Hamilton Jet"},
    {285, "sea_recovery", "Sea Recovery"},
    {286, "coelmo_srl_italy", "Coelmo SRL Italy"},
    {295, "bep_marine", "BEP Marine"},
    {304, "empir_bus", "Empir Bus"},
    {305, "novatel", "NovAtel"},
    {306, "sleipner_motor", "Sleipner Motor"},
    {307, "mbw_technologies", "MBW Technologies"},
    {315, "icom", "ICOM"},
    {328, "qwerty", "Qwerty"},
    {329, "dief", "Dief"},
    {341, "boening_automationstechnologie", "Boening Automationstechnologie"},
    {345, "korean_maritime_university", "Korean Maritime University"},
    {351, "thrane_and_thrane", "Thrane and Thrane"},
    {355, "mastervolt", "Mastervolt"},
    {356, "fischer_panda_generators", "Fischer Panda Generators"},
    {358, "victron_energy", "Victron Energy"},
    {370, "rolls_royce_marine", "Rolls Royce Marine"},
    {373, "electronic_design", "Electronic Design"},
    {374, "northern_lights", "Northern Lights"},
    {378, "glendinning", "Glendinning"},
    {381, "b_and_g", "B & G"},
    {384, "rose_point_navigation_systems", "Rose Point Navigation Systems"},
    {385, "johnson_outdoors_marine_electronics_inc_geonav",
     "Johnson Outdoors Marine Electronics Inc Geonav"},
    {394, "capi_2", "Capi 2"},
    {396, "beyond_measure", "Beyond Measure"},
    {400, "livorsi_marine", "Livorsi Marine"},
    {404, "comnav", "ComNav"},
    {409, "chetco", "Chetco"},
    {419, "fusion_electronics", "Fusion Electronics"},
    {421, "standard_horizon", "Standard Horizon"},
    {422, "true_heading", "True Heading"},
    {426, "egersund_marine_electronics", "Egersund Marine Electronics"},
    {427, "em_trak_marine_electronics", "em-trak Marine Electronics"},
    {431, "tohatsu_co_jp", "Tohatsu Co, JP"},
    {437, "digital_yacht", "Digital Yacht"},
    {438, "comar_systems_limited", "Comar Systems Limited"},
    {440, "cummins", "Cummins"},
    {443, "vdo_aka_continental_corporation", "VDO (aka Continental-Corporation)"},
    {451, "parker_hannifin_aka_village_marine_tech", "Parker Hannifin aka Village Marine Tech"},
    {459, "alltek_marine_electronics", "Alltek Marine Electronics"},
    {460, "san_giorgio_s_e_i_n", "SAN GIORGIO S.E.I.N"},
    {466, "veethree_electronics_and_marine", "Veethree Electronics & Marine"},
    {470, "si_tex_marine_electronics", "SI-TEX Marine Electronics"},
    {471, "sea_cross_marine", "Sea Cross Marine"},
    {475, "gme_aka_standard_communications", "GME aka Standard Communications"},
    {476, "humminbird_marine_electronics", "Humminbird Marine Electronics"},
    {478, "ocean_sat", "Ocean Sat"},
    {481, "chetco_digital_instruments", "Chetco Digital Instruments"},
    {493, "watcheye", "Watcheye"},
    {499, "lcj_capteurs", "Lcj Capteurs"},
    {502, "attwood_marine", "Attwood Marine"},
    {503, "naviop_s_r_l", "Naviop S.R.L."},
    {504, "vesper_marine", "Vesper Marine"},
    {510, "marinesoft", "Marinesoft"},
    {513, "simarine", "Simarine"},
    {517, "noland_engineering", "NoLand Engineering"},
    {518, "transas_usa", "Transas USA"},
    {529, "national_instruments_korea", "National Instruments Korea"},
    {530, "national_marine_electronics_association", "National Marine Electronics Association"},
    {532, "onwa_marine", "Onwa Marine"},
    {540, "webasto", "Webasto"},
    {571, "marinecraft_south_korea", "Marinecraft (South Korea)"},
    {573, "mcmurdo_group_aka_orolia", "McMurdo Group aka Orolia"},
    {578, "advansea", "Advansea"},
    {579, "kvh", "KVH"},
    {580, "san_jose_technology", "San Jose Technology"},
    {583, "yacht_control", "Yacht Control"},
    {586, "suzuki_motor", "Suzuki Motor"},
    {591, "us_coast_guard", "US Coast Guard"},
    {595, "ship_module_aka_customware", "Ship Module aka Customware"},
    {600, "aquatic_av", "Aquatic AV"},
    {605, "aventics", "Aventics"},
    {606, "intellian", "Intellian"},
    {612, "samwonit", "SamwonIT"},
    {614, "arlt_tecnologies", "Arlt Tecnologies"},
    {637, "bavaria_yachts", "Bavaria Yachts"},
    {641, "diverse_yacht_services", "Diverse Yacht Services"},
    {644, "wema_u_s_a_dba_kus", "Wema U.S.A dba KUS"},
    {658, "shenzhen_jiuzhou_himunication", "Shenzhen Jiuzhou Himunication"},
    {688, "rockford", "Rockford"},
    {699, "harman_international", "Harman International"},
    {704, "jl_audio", "JL Audio"},
    {708, "lars_thrane", "Lars Thrane"},
    {715, "autonnic", "Autonnic"},
    {717, "yacht_devices", "Yacht Devices"},
    {734, "reap_systems", "REAP Systems"},
    {735, "aem_performance_electronics", "AEM Performance Electronics"},
    {739, "lxnav", "LxNav"},
    {741, "littelfuse_inc_formerly_carling_technologies",
     "Littelfuse, Inc (formerly Carling Technologies)"},
    {743, "daemyung", "DaeMyung"},
    {744, "woosung", "Woosung"},
    {748, "isotta_ifra_srl", "ISOTTA IFRA srl"},
    {773, "clarion_us", "Clarion US"},
    {776, "hmi_systems", "HMI Systems"},
    {777, "ocean_signal", "Ocean Signal"},
    {778, "seakeeper", "Seakeeper"},
    {781, "poly_planar", "Poly Planar"},
    {785, "fischer_panda_de", "Fischer Panda DE"},
    {795, "broyda_industries", "Broyda Industries"},
    {796, "canadian_automotive", "Canadian Automotive"},
    {797, "tides_marine", "Tides Marine"},
    {798, "lumishore", "Lumishore"},
    {799, "still_water_designs_and_audio", "Still Water Designs and Audio"},
    {802, "bj_technologies_beneteau", "BJ Technologies (Beneteau)"},
    {803, "gill_sensors", "Gill Sensors"},
    {811, "blue_water_desalination", "Blue Water Desalination"},
    {815, "flir", "FLIR"},
    {824, "undheim_systems", "Undheim Systems"},
    {826, "lewmar", "Lewmar"},
    {838, "teamsurv", "TeamSurv"},
    {844, "fell_marine", "Fell Marine"},
    {847, "oceanvolt", "Oceanvolt"},
    {862, "prospec", "Prospec"},
    {868, "data_panel", "Data Panel"},
    {890, "l3_technologies", "L3 Technologies"},
    {894, "rhodan_marine_systems", "Rhodan Marine Systems"},
    {896, "nexfour_solutions", "Nexfour Solutions"},
    {905, "asa_electronics", "ASA Electronics"},
    {909, "marines_co_south_korea", "Marines Co (South Korea)"},
    {911, "nautic_on", "Nautic-on"},
    {917, "sentinel", "Sentinel"},
    {929, "jl_marine_systems", "JL Marine Systems"},
    {930, "ecotronix", "Ecotronix"},
    {944, "zontisa_marine", "Zontisa Marine"},
    {951, "exor_international", "EXOR International"},
    {962, "timbolier_industries", "Timbolier Industries"},
    {963, "tjc_micro", "TJC Micro"},
    {968, "cox_powertrain", "Cox Powertrain"},
    {969, "blue_seas", "Blue Seas"},
    {981, "kobelt_manufacturing", "Kobelt Manufacturing"},
    {992, "blue_ocean_iot", "Blue Ocean IOT"},
    {997, "xenta_systems", "Xenta Systems"},
    {999, "signal_k", "Signal K"},
    {1004, "ultraflex", "Ultraflex"},
    {1008, "lintest_smartboat", "Lintest SmartBoat"},
    {1011, "soundmax", "Soundmax"},
    {1020, "team_italia_marine_onyx_marine_automation_s_r_l",
     "Team Italia Marine (Onyx Marine Automation s.r.l)"},
    {1021, "entratech", "Entratech"},
    {1022, "itc", "ITC"},
    {1029, "the_marine_guardian", "The Marine Guardian"},
    {1047, "sonic", "Sonic"},
    {1051, "pronav", "ProNav"},
    {1053, "vetus_maxwell_inc", "Vetus Maxwell INC."},
    {1056, "lithium_pros", "Lithium Pros"},
    {1059, "boatrax", "Boatrax"},
    {1062, "marol_co_ltd", "Marol Co ltd"},
    {1065, "calypso_instruments", "CALYPSO Instruments"},
    {1066, "spot_zero_water", "Spot Zero Water"},
    {1069, "lithionics_battery", "Lithionics Battery"},
    {1070, "quick_teck_electronics", "Quick-teck Electronics"},
    {1075, "uniden_america", "Uniden America"},
    {1083, "nauticoncept", "Nauticoncept"},
    {1084, "shadow_caster_led_lighting", "Shadow-Caster LED lighting"},
    {1085, "wet_sounds", "Wet Sounds"},
    {1088, "e_t_a_circuit_breakers", "E-T-A Circuit Breakers"},
    {1092, "scheiber", "Scheiber"},
    {1100, "smart_yachts_international_limited", "Smart Yachts International Limited"},
    {1109, "dockmate", "Dockmate"},
    {1114, "bobs_machine", "Bobs Machine"},
    {1118, "l3harris_asv", "L3Harris ASV"},
    {1119, "balmar", "Balmar"},
    {1120, "elettromedia", "Elettromedia"},
    {1127, "electromaax", "Electromaax"},
    {1140, "across_oceans_systems", "Across Oceans Systems"},
    {1145, "kiwi_yachting", "Kiwi Yachting"},
    {1150, "bsb_artificial_intelligence", "BSB Artificial Intelligence"},
    {1151, "orca_technologies", "Orca Technologies"},
    {1154, "tbs_electronics", "TBS Electronics"},
    {1158, "technoton_electroics", "Technoton Electroics"},
    {1160, "mg_energy_systems", "MG Energy Systems"},
    {1169, "sea_machine_robotics", "Sea Machine Robotics"},
    {1171, "vista_manufacturing", "Vista Manufacturing"},
    {1183, "zipwake", "Zipwake"},
    {1186, "sailmon", "Sailmon"},
    {1192, "airmoniq_pro_kft", "Airmoniq Pro Kft"},
    {1194, "sierra_marine", "Sierra Marine"},
    {1200, "xinuo_information_technology_xiamen", "Xinuo Information Technology (Xiamen)"},
    {1218, "septentrio", "Septentrio"},
    {1233, "nke_marine_electronics", "NKE Marine Electronics"},
    {1238, "supertrack_aps", "SuperTrack Aps"},
    {1239, "honda_electronics", "Honda Electronics"},
    {1245, "raritan_engineering", "Raritan Engineering"},
    {1249, "integrated_power_solutions_ag", "Integrated Power Solutions AG"},
    {1260, "interactive_technologies", "Interactive Technologies"},
    {1283, "ltg_tech", "LTG-Tech"},
    {1299, "energy_solutions_uk", "Energy Solutions (UK)"},
    {1300, "watt_fuel_cell", "WATT Fuel Cell"},
    {1302, "pro_mainer", "Pro Mainer"},
    {1305, "dragonfly_energy", "Dragonfly Energy"},
    {1306, "koden_electronics", "Koden Electronics"},
    {1311, "humphree", "Humphree"},
    {1316, "hinkley_yachts", "Hinkley Yachts"},
    {1317, "global_marine_management_gmbh_gmm", "Global Marine Management GmbH (GMM)"},
    {1320, "triskel_marine", "Triskel Marine"},
    {1330, "warwick_control_technologies", "Warwick Control Technologies"},
    {1331, "dolphin_charger", "Dolphin Charger"},
    {1337, "barnacle_systems", "Barnacle Systems"},
    {1348, "radian_iot", "Radian IoT"},
    {1353, "ocean_led_marine", "Ocean LED Marine"},
    {1359, "blunav", "BluNav"},
    {1361, "ova_nantong_saiyang_electronics_co_ltd", "OVA (Nantong Saiyang Electronics Co., Ltd)"},
    {1368, "rad_propulsion", "RAD Propulsion"},
    {1369, "electric_yacht", "Electric Yacht"},
    {1372, "elco_motor_yachts", "Elco Motor Yachts"},
    {1384, "tecnoseal_foundry_s_r_l", "Tecnoseal Foundry S.r.l"},
    {1385, "pro_charging_systems", "Pro Charging Systems"},
    {1389, "evex", "EVEX"},
    {1398, "gobius_sensor_technology", "Gobius Sensor Technology"},
    {1403, "arco_marine", "Arco Marine"},
    {1408, "lenco_marine", "Lenco Marine"},
    {1413, "naocontrol", "Naocontrol"},
    {1417, "revatek", "Revatek"},
    {1438, "aeolionics", "Aeolionics"},
    {1439, "predictwind", "PredictWind"},
    {1440, "egis_mobile_electric", "Egis Mobile Electric"},
    {1445, "starboard_yacht_group", "Starboard Yacht Group"},
    {1446, "roswell_marine", "Roswell Marine"},
    {1451, "epropulsion_guangdong_epropulsion_technology_ltd",
     "ePropulsion (Guangdong ePropulsion Technology Ltd.)"},
    {1452, "micro_air", "Micro-Air"},
    {1453, "vital_battery", "Vital Battery"},
    {1458, "ride_controller", "Ride Controller"},
    {1460, "tocaro_blue", "Tocaro Blue"},
    {1461, "vanquish_yachts", "Vanquish Yachts"},
    {1471, "ft_technologies", "FT Technologies"},
    {1478, "alps_alpine", "Alps Alpine"},
    {1481, "e_force_marine", "E-Force Marine"},
    {1482, "cmc_marine", "CMC Marine"},
    {1483, "nanjing_sandemarine_information_technology",
     "Nanjing Sandemarine Information Technology"},
    {1850, "teleflex_marine_seastar_solutions", "Teleflex Marine (SeaStar Solutions)"},
    {1851, "raymarine", "Raymarine"},
    {1852, "navionics", "Navionics"},
    {1853, "japan_radio", "Japan Radio"},
    {1854, "northstar_technologies", "Northstar Technologies"},
    {1855, "furuno", "Furuno"},
    {1856, "trimble", "Trimble"},
    {1857, "simrad", "Simrad"},
    {1858, "litton", "Litton"},
    {1859, "kvasar", "Kvasar"},
    {1860, "mmp", "MMP"},
    {1861, "vector_cantech", "Vector Cantech"},
    {1862, "yamaha_marine", "Yamaha Marine"},
    {1863, "faria_instruments", "Faria Instruments"},
}};
template <std::size_t N, std::size_t M>
[[nodiscard]] constexpr std::array<std::string_view, N> spread(
    const std::array<code_name, M>& codes, bool titles) noexcept {
  std::array<std::string_view, N> out{};
  for (const code_name& c : codes) out[c.code] = titles ? c.title : c.name;
  return out;
}
}  // namespace detail

constexpr std::array<std::string_view, 2048> lookup_names(manufacturer_code) noexcept {
  return detail::spread<2048>(detail::manufacturer_codes, false);
}
constexpr std::array<std::string_view, 2048> lookup_titles(manufacturer_code) noexcept {
  return detail::spread<2048>(detail::manufacturer_codes, true);
}

/// The industry a device belongs to (3 bits); 4 is marine. 5 (industrial) is named, so it is a
/// value although a 3-bit lookup's top three raw values are otherwise sentinels.
enum class industry_group : std::uint8_t {
  global = 0,
  highway = 1,
  agriculture = 2,
  construction = 3,
  marine = 4,
  industrial = 5,
};
constexpr std::array<std::string_view, 6> lookup_names(industry_group) noexcept {
  return {"global", "highway", "agriculture", "construction", "marine", "industrial"};
}
constexpr std::array<std::string_view, 6> lookup_titles(industry_group) noexcept {
  return {"Global", "Highway", "Agriculture", "Construction", "Marine Industry", "Industrial"};
}

/// A device's class (7 bits): what kind of equipment it is. 125 (entertainment) is named, so it
/// is a value although a 7-bit lookup's top three raw values are otherwise sentinels.
enum class device_class : std::uint8_t {
  reserved_2000 = 0,
  system_tools = 10,
  safety = 20,
  internetwork = 25,
  electrical_distribution = 30,
  electrical_generation = 35,
  steering_and_control_surfaces = 40,
  propulsion = 50,
  navigation = 60,
  communication = 70,
  sensor_communication_interface = 75,
  instrumentation = 80,
  external_environment = 85,
  internal_environment = 90,
  deck_cargo_fishing = 100,
  human_interface = 110,
  display = 120,
  entertainment = 125,
};
constexpr std::array<std::string_view, 126> lookup_names(device_class) noexcept {
  std::array<std::string_view, 126> a{};
  a[0] = "reserved_2000";
  a[10] = "system_tools";
  a[20] = "safety";
  a[25] = "internetwork";
  a[30] = "electrical_distribution";
  a[35] = "electrical_generation";
  a[40] = "steering_and_control_surfaces";
  a[50] = "propulsion";
  a[60] = "navigation";
  a[70] = "communication";
  a[75] = "sensor_communication_interface";
  a[80] = "instrumentation";
  a[85] = "external_environment";
  a[90] = "internal_environment";
  a[100] = "deck_cargo_fishing";
  a[110] = "human_interface";
  a[120] = "display";
  a[125] = "entertainment";
  return a;
}
constexpr std::array<std::string_view, 126> lookup_titles(device_class) noexcept {
  std::array<std::string_view, 126> a{};
  a[0] = "Reserved for 2000 Use";
  a[10] = "System tools";
  a[20] = "Safety systems";
  a[25] = "Internetwork device";
  a[30] = "Electrical Distribution";
  a[35] = "Electrical Generation";
  a[40] = "Steering and Control surfaces";
  a[50] = "Propulsion";
  a[60] = "Navigation";
  a[70] = "Communication";
  a[75] = "Sensor Communication Interface";
  a[80] = "Instrumentation/general systems";
  a[85] = "External Environment";
  a[90] = "Internal Environment";
  a[100] = "Deck + cargo + fishing equipment systems";
  a[110] = "Human Interface";
  a[120] = "Display";
  a[125] = "Entertainment";
  return a;
}

/// A device's function within its class (8 bits), named by (device class, function): the
/// same function number means different things in different classes.
struct device_functions {
  static constexpr std::array<keyed_name, 106> entries{{
      {10, 130, "diagnostic", "Diagnostic"},
      {10, 140, "bus_traffic_logger", "Bus Traffic Logger"},
      {20, 110, "alarm_enunciator", "Alarm Enunciator"},
      {20, 130, "emergency_position_indicating_radio_beacon_epirb",
       "Emergency Position Indicating Radio Beacon (EPIRB)"},
      {20, 135, "man_overboard", "Man Overboard"},
      {20, 140, "voyage_data_recorder", "Voyage Data Recorder"},
      {20, 150, "camera", "Camera"},
      {25, 130, "pc_gateway", "PC Gateway"},
      {25, 131, "nmea_2000_to_analog_gateway", "NMEA 2000 to Analog Gateway"},
      {25, 132, "analog_to_nmea_2000_gateway", "Analog to NMEA 2000 Gateway"},
      {25, 133, "nmea_2000_to_serial_gateway", "NMEA 2000 to Serial Gateway"},
      {25, 135, "nmea_0183_gateway", "NMEA 0183 Gateway"},
      {25, 136, "nmea_network_gateway", "NMEA Network Gateway"},
      {25, 137, "nmea_2000_wireless_gateway", "NMEA 2000 Wireless Gateway"},
      {25, 140, "router", "Router"},
      {25, 150, "bridge", "Bridge"},
      {25, 160, "repeater", "Repeater"},
      {30, 130, "binary_event_monitor", "Binary Event Monitor"},
      {30, 140, "load_controller", "Load Controller"},
      {30, 141, "ac_dc_input", "AC/DC Input"},
      {30, 150, "function_controller", "Function Controller"},
      {35, 140, "engine", "Engine"},
      {35, 141, "dc_generator_alternator", "DC Generator/Alternator"},
      {35, 142, "solar_panel_solar_array", "Solar Panel (Solar Array)"},
      {35, 143, "wind_generator_dc", "Wind Generator (DC)"},
      {35, 144, "fuel_cell", "Fuel Cell"},
      {35, 145, "network_power_supply", "Network Power Supply"},
      {35, 151, "ac_generator", "AC Generator"},
      {35, 152, "ac_bus", "AC Bus"},
      {35, 153, "ac_mains_utility_shore", "AC Mains (Utility/Shore)"},
      {35, 154, "ac_output", "AC Output"},
      {35, 160, "power_converter_battery_charger", "Power Converter - Battery Charger"},
      {35, 161, "power_converter_battery_charger_plus_inverter",
       "Power Converter - Battery Charger+Inverter"},
      {35, 162, "power_converter_inverter", "Power Converter - Inverter"},
      {35, 163, "power_converter_dc", "Power Converter - DC"},
      {35, 170, "battery", "Battery"},
      {35, 180, "engine_gateway", "Engine Gateway"},
      {40, 130, "follow_up_controller", "Follow-up Controller"},
      {40, 140, "mode_controller", "Mode Controller"},
      {40, 150, "autopilot", "Autopilot"},
      {40, 155, "rudder", "Rudder"},
      {40, 160, "heading_sensors", "Heading Sensors"},
      {40, 170, "trim_tabs_interceptors", "Trim (Tabs)/Interceptors"},
      {40, 180, "attitude_pitch_roll_yaw_control", "Attitude (Pitch, Roll, Yaw) Control"},
      {50, 130, "engineroom_monitoring", "Engineroom Monitoring"},
      {50, 140, "engine", "Engine"},
      {50, 141, "dc_generator_alternator", "DC Generator/Alternator"},
      {50, 150, "engine_controller", "Engine Controller"},
      {50, 151, "ac_generator", "AC Generator"},
      {50, 155, "motor", "Motor"},
      {50, 160, "engine_gateway", "Engine Gateway"},
      {50, 165, "transmission", "Transmission"},
      {50, 170, "throttle_shift_control", "Throttle/Shift Control"},
      {50, 180, "actuator", "Actuator"},
      {50, 190, "gauge_interface", "Gauge Interface"},
      {50, 200, "gauge_large", "Gauge Large"},
      {50, 210, "gauge_small", "Gauge Small"},
      {60, 130, "bottom_depth", "Bottom Depth"},
      {60, 135, "bottom_depth_speed", "Bottom Depth/Speed"},
      {60, 136, "bottom_depth_speed_temperature", "Bottom Depth/Speed/Temperature"},
      {60, 140, "ownship_attitude", "Ownship Attitude"},
      {60, 145, "ownship_position_gnss", "Ownship Position (GNSS)"},
      {60, 150, "ownship_position_loran_c", "Ownship Position (Loran C)"},
      {60, 155, "speed", "Speed"},
      {60, 160, "turn_rate_indicator", "Turn Rate Indicator"},
      {60, 170, "integrated_navigation", "Integrated Navigation"},
      {60, 175, "integrated_navigation_system", "Integrated Navigation System"},
      {60, 190, "navigation_management", "Navigation Management"},
      {60, 195, "automatic_identification_system_ais", "Automatic Identification System (AIS)"},
      {60, 200, "radar", "Radar"},
      {60, 201, "infrared_imaging", "Infrared Imaging"},
      {60, 205, "ecdis", "ECDIS"},
      {60, 210, "ecs", "ECS"},
      {60, 220, "direction_finder", "Direction Finder"},
      {60, 230, "voyage_status", "Voyage Status"},
      {70, 130, "epirb", "EPIRB"},
      {70, 140, "ais", "AIS"},
      {70, 150, "dsc", "DSC"},
      {70, 160, "data_receiver_transceiver", "Data Receiver/Transceiver"},
      {70, 170, "satellite", "Satellite"},
      {70, 180, "radio_telephone_mf_hf", "Radio-telephone (MF/HF)"},
      {70, 190, "radiotelephone", "Radiotelephone"},
      {75, 130, "temperature", "Temperature"},
      {75, 140, "pressure", "Pressure"},
      {75, 150, "fluid_level", "Fluid Level"},
      {75, 160, "flow", "Flow"},
      {75, 170, "humidity", "Humidity"},
      {80, 130, "time_date_systems", "Time/Date Systems"},
      {80, 140, "vdr", "VDR"},
      {80, 150, "integrated_instrumentation", "Integrated Instrumentation"},
      {80, 160, "general_purpose_displays", "General Purpose Displays"},
      {80, 170, "general_sensor_box", "General Sensor Box"},
      {80, 180, "weather_instruments", "Weather Instruments"},
      {80, 190, "transducer_general", "Transducer/General"},
      {80, 200, "nmea_0183_converter", "NMEA 0183 Converter"},
      {85, 130, "atmospheric", "Atmospheric"},
      {85, 160, "aquatic", "Aquatic"},
      {90, 130, "hvac", "HVAC"},
      {100, 130, "scale_catch", "Scale (Catch)"},
      {110, 130, "button_interface", "Button Interface"},
      {110, 135, "switch_interface", "Switch Interface"},
      {110, 140, "analog_interface", "Analog Interface"},
      {120, 130, "display", "Display"},
      {120, 140, "alarm_enunciator", "Alarm Enunciator"},
      {125, 130, "multimedia_player", "Multimedia Player"},
      {125, 140, "multimedia_controller", "Multimedia Controller"},
  }};
};

}  // namespace seawire::nmea2000
