// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "brc_line.h"
#include "odometry.h"
#include "result.h"
#include "room.h"
#include "robot_profile.h"
#include "schedule.h"
#include "sensor_snapshot.h"
#include "song.h"
#include "world.h"

#include <array>
#include <chrono>
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace sim {

using Microseconds = std::chrono::microseconds;

// Noise on the line, as probabilities per byte sent by the robot.
struct FaultRates {
    double corruptByte = 0; // replace a byte with a random one
    double strayHeader = 0; // insert a 19 before a byte
    double dropByte = 0;    // leave a byte out
};

// The robot's side of the Open Interface for one profile, with its own
// clock: nothing happens until advance() is called. Bytes from the client go
// in through receive(); what the robot says comes out of takeOutput().
class VirtualRobot {
public:
    explicit VirtualRobot(const oi::RobotProfile &profile, std::uint32_t seed = 1);
    ~VirtualRobot();
    VirtualRobot(const VirtualRobot &) = delete;
    VirtualRobot &operator=(const VirtualRobot &) = delete;

    const oi::RobotProfile &robotProfile() const;

    // --- The serial line ---
    void receive(std::span<const std::uint8_t> bytes);
    oi::Bytes takeOutput();
    // True while stream frames go out (148 started them, 150 did not pause them).
    bool streaming() const;
    // The baud the robot talks at now (changed by opcode 129).
    int baud() const;

    // --- Time ---
    void advance(Microseconds dt);
    Microseconds now() const;
    // Stream frames go out when the clock reaches a multiple of this.
    static constexpr Microseconds kStreamPeriod{15'000};
    // How long until the robot next says something of its own accord (a
    // stream frame); replies go out as the question comes in.
    Microseconds untilNextFrame() const { return kStreamPeriod - now() % kStreamPeriod; }

    // --- World and pose ---
    void setWorld(World world);
    const World &world() const;
    void placeAt(oi::Pose pose); // also used by tests to lift it off a cliff
    const oi::Pose &truePose() const;
    // From now on the robot is robot `id` of `room`, which others may share:
    // at every millisecond of its clock it takes the room's floor (instead of
    // setWorld's), meets the other robots as bodies, writes its pose there
    // and takes a hand move or lift made through the room. It starts where
    // the room has it. The room must already hold `id`.
    void joinRoom(std::shared_ptr<Room> room, RobotId id);
    // The robot's real wheels (default: the documents' 72 mm and 235 mm). The
    // firmware knows only the documented ones: it drives and counts by them,
    // so a wheel larger than documented carries the body farther than its
    // encoder counts, its distance and angle packets say, as on a real robot.
    void setWheels(const oi::WheelGeometry &wheels);
    const oi::WheelGeometry &wheels() const;
    // Lifts wheels off the floor by hand (wheel drops), beside what the world does.
    void setWheelsLifted(bool left, bool right, bool caster = false);
    void pressButtons(std::uint8_t packet18Bits); // held until released with 0
    // The Clean/Power button of a Roomba 500 or Create 2 (packet 18's
    // Clean): held for 2 s, it switches the robot off (the OI's Off, silent
    // and deaf as asleep); pressed and let go while off, or a BRC pulse,
    // switches it on in Off mode, waiting for Start.
    bool switchedOff() const;

    // --- What the robot shows and stores ---
    oi::OiMode mode() const;
    // A Roomba 500 or Create 2 / Roomba 600 sleeps after 5 minutes in
    // Passive without a BRC pulse (the Create 2 document's "Power Saving";
    // ERRATA 17); either sleeps after Power (133). The Create never sleeps.
    // Asleep it hears nothing and says nothing, Start included.
    bool asleep() const;
    // The Baud Rate Change pin: low while `low`. A pulse wakes a sleeping
    // robot as it ends (into Off mode, waiting for Start), except on its dock
    // before release-3.8.2 / release-stm32-3.7.7; bytes sent before the pulse
    // ended and Quirks::wakeTime after it are lost. Awake, a pulse in
    // Passive restarts the count to sleep. Three pulses of 50-500 ms, from
    // 2 s after waking (or power-on), set 19200 baud. The Create shows the
    // pin in packet 32, active low.
    void setBrcLow(bool low);
    // A serial adapter's RTS or DTR line (or both) asserted or released: it
    // reaches the BRC pin only where the cable joins them
    // (Quirks::brcWiredTo), and asserted pulls the pin low, as on FTDI-style
    // cables.
    void setModemLine(oi::BrcLine lines, bool asserted);
    // e.g. "release-3.4.1"; printed on Reset. Release-3.2.x sleeps while
    // pulsed (Quirks::sleepsWhilePulsed).
    void setFirmwareRelease(std::string release);
    // What only some robots do in the field (off by default, as the
    // documents say robots behave).
    struct Quirks {
        // Firmware release-3.2.x: sleeps after 5 minutes in Passive whatever
        // BRC pulses come; a pulse still wakes it (off the dock). A robot
        // whose setFirmwareRelease() is release-3.2.x does so without it.
        bool sleepsWhilePulsed = false;
        // Some Wi-Fi Roomba 600s: packet 35 reads one too high (Passive 2,
        // Safe 3, Full 4).
        bool reportsModeOneHigh = false;
        // The cable: which adapter line reaches the BRC pin (Rts, Dtr, or
        // None for a cable without the BRC wire).
        oi::BrcLine brcWiredTo = oi::BrcLine::Rts;
        // How long after a wake pulse ends the robot listens: the documents
        // imply a moment (RobotProfile::kWakeMs); some robots take up to 2 s.
        Microseconds wakeTime{std::chrono::milliseconds(oi::RobotProfile::kWakeMs)};
        // A battery gauge gone wrong: packet 25 reads the charge plus the
        // capacity, more than the pack can hold.
        bool reportsChargeAboveCapacity = false;
        // A Bluetooth serial adapter or a Wi-Fi bridge that hands on what
        // the robot says in bunches this far apart, on time but held (0:
        // each byte as it is sent). An FTDI adapter's latency timer is 16 ms.
        Microseconds bunch{0};
    };
    void setQuirks(Quirks quirks);
    const Quirks &quirks() const;
    struct Leds {
        std::uint8_t bits = 0, powerColor = 0, powerIntensity = 0;
        std::uint8_t weekdayBits = 0, schedulingBits = 0;
        std::array<std::uint8_t, 4> digitSegments{}; // digit 3..0, segment bits
    };
    const Leds &leds() const;
    std::optional<oi::Song> song(int slot) const;
    bool songPlaying() const; // packet 37: a song started by Play (141)
    bool sounding() const;    // anything from the speaker: a song, the Start beep, the Stop song
    oi::CleaningSchedule schedule() const;
    struct DayTime {
        oi::Weekday day = oi::Weekday::Sunday;
        int hour = 0, minute = 0;
    };
    DayTime clock() const;
    std::uint8_t motorBits() const;                // 138 (brushes/vacuum or low side drivers)
    std::array<int, 3> motorPwm() const;           // 144, as sent
    std::uint8_t digitalOutputs() const;           // 147 (Create 1)
    oi::Bytes script() const;                      // 152 body (Create 1)
    // Charged in Passive (or Off) on the dock; in Safe or Full on the dock
    // it drains by the robot's own load, as the Create 2 document warns.
    // While it charges, a Roomba 500 / 600 prints a status line once a
    // second between frames ("bat:   min 0  sec 12  mV 16421  mA 1183 ..."),
    // and Reset on the dock adds the charger's lines to the banner.
    // The charge the pack holds (what the robot's gauge, packet 25, counts
    // may differ: see Battery). Setting it sets the gauge to it too.
    double batteryChargeMah() const;
    void setBatteryChargeMah(double mah);
    // The pack: new by default. An aged one holds less than the documented
    // 3000 mAh (fadePercent of it lost) and sags more under load (its
    // internal resistance, mΩ), while the firmware still claims 3000 mAh
    // (26). The gauge (25) counts the current from what it was told: at
    // boot (Reset) it is re-seeded from the voltage (the banner says
    // "estimate-battery-level-from-voltage"), which a worn pack's sag puts
    // too low, and at the end of a charge it is set full. Nearly flat under
    // load (below kBrownOutMv) Safe and Full fall to Passive by themselves
    // ("battery"). A pack run flat (under 1 % of its charge) and docked
    // shows a charging fault (21 = 5) until a Reset.
    static constexpr double kNewPackResistanceMohm = 250;
    static constexpr double kBrownOutMv = 12800;
    struct Battery {
        double fadePercent = 0;                          // 0 to 90
        double resistanceMohm = kNewPackResistanceMohm;  // 50 to 5000
        friend bool operator==(const Battery &, const Battery &) = default;
    };
    // Refused (false, nothing changed) outside those ranges; the pack starts
    // at 90 % of what it holds, as a new robot does.
    bool setBattery(const Battery &battery);
    const Battery &battery() const;
    // What packet 25 reads now (the gauge), mAh.
    double batteryGaugeMah() const;
    // Why Safe (or Full) last fell back to Passive ("cliff", "wheel drop", "charger", "battery"), or empty.
    std::string lastSafetyStop() const;

    // --- Faults ---
    void setFaultRates(FaultRates rates);
    void stall(Microseconds duration); // says nothing for this long
    void disconnect();                 // the cable is pulled: nothing in or out until reconnect()
    void reconnect();
    bool disconnected() const;

private:
    struct State;
    std::unique_ptr<State> m_state;
};

} // namespace sim
