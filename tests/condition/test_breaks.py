"""Fracture and channel removal found from the signals alone."""

import numpy as np
import pytest

from pipeline.condition.breaks import (
    DECADE_CAUSE,
    find_fracture,
    find_removal,
    reading_step,
)
from pipeline.simulate.pull import PullTruth, simulate_pull

#: A 13x50 chain on a 0.9 m gauge: stiffness E0 [N], gauge length [m], force noise [N],
#: gauge noise [m] and gauge resolution [m] as a lab's clip-on extensometer logs them.
E0, GAUGE, FORCE_NOISE, GAUGE_NOISE, RESOLUTION = 1.1e7, 0.9, 50.0, 2e-6, 1e-5


def _loading(seed: int, samples: int = 6000) -> tuple[np.ndarray, np.ndarray]:
    """A first loading from 5 to 34 kN with a quantised extensometer [N], [m]."""
    rng = np.random.default_rng(seed)
    true_force = np.linspace(5e3, 34e3, samples)
    force = true_force + rng.normal(0.0, FORCE_NOISE, samples)
    elongation = true_force / E0 * GAUGE + rng.normal(0.0, GAUGE_NOISE, samples)
    return force, np.round(elongation / RESOLUTION) * RESOLUTION


def test_a_quantised_gauge_flickering_by_a_step_is_not_taken_off():
    # the reading flickers a step up and a step down about its true value; that
    # two-step fall while the force rises is noise, not a gauge running backwards
    flagged = [seed for seed in range(100) if find_removal(*_loading(seed)) is not None]
    assert flagged == []


def test_a_quantised_gauge_that_falls_back_is_taken_off():
    force, channel = _loading(0)
    fallen = channel.copy()
    fallen[4000:] -= 10 * RESOLUTION  # slips back by 0.1 mm and stays there
    removal = find_removal(force, fallen)
    assert removal is not None and removal.reason == "runs backwards"
    assert removal.position == 4000


def test_a_noisy_channel_dipping_for_a_sample_is_not_taken_off():
    # a machine's displacement read to about 0.03 mm (a real CCFatigue quasi-static log):
    # one reading falls six times its noise below the running maximum, the next is back
    rng = np.random.default_rng(1)
    force = np.linspace(10e3, 530e3, 200)
    channel = 0.4e-3 + force / 1e10 + rng.normal(0.0, 0.007e-3, 200)  # [m]
    assert int(np.argmax(channel[:150])) < 140  # the running maximum: an earlier noise peak
    channel[150] = channel[:150].max() - 6 * 0.007e-3
    assert find_removal(force, channel) is None
    channel[150:153] = channel[:150].max() - 6 * 0.007e-3  # three in a row: it fell back
    removal = find_removal(force, channel)
    assert removal is not None and removal.reason == "runs backwards"
    assert removal.position == 150


def test_a_jump_by_ten_is_named_as_a_lost_decimal_mark():
    # a real Bluehill export re-saved by a spreadsheet: 0.9966 mm, then 10.114 for 1.0114
    force, channel = _loading(3)
    shifted = channel.copy()
    shifted[4000:] *= 10.0
    removal = find_removal(force, shifted)
    assert removal is not None and removal.reason == "jumps" and removal.position == 4000
    assert removal.cause == DECADE_CAUSE


def test_a_slip_is_named_as_such():
    force, channel = _loading(4)
    slipped = channel.copy()
    slipped[4000:] += 0.3 * np.ptp(channel)  # the knife edge slips: a step, not a decade
    removal = find_removal(force, slipped)
    assert removal is not None and removal.reason == "jumps" and removal.position == 4000
    assert removal.cause == "taken off or slipped"


@pytest.mark.parametrize("seed", range(5))
def test_an_extensometer_taken_off_far_below_is_cut_there_not_at_the_start(seed):
    # a real Bluehill pull in Polish: the extensometer hangs at -0.13 (strain) once taken
    # off, far below its travel on the specimen; half a per cent of that whole range
    # exceeded what it moved over the first twentieth of the record while the crosshead
    # took up its travel, and it was cut as frozen from sample 0
    force, channel = _loading(seed)
    crosshead = 3.0 * channel + 2e-3  # the machine's travel: the specimen and the frame's
    off = channel.copy()
    rng = np.random.default_rng(seed)
    off[4000:] = -30 * np.ptp(channel[:4000]) + rng.normal(0.0, 20 * RESOLUTION, 2000)
    removal = find_removal(force, off, [crosshead])
    assert removal is not None and removal.position == 4000
    assert removal.reason in ("jumps", "runs backwards")


def test_reading_step_is_the_resolution_of_a_quantised_reading():
    _, channel = _loading(1)
    assert reading_step(channel) == pytest.approx(RESOLUTION, rel=1e-9)
    assert reading_step(np.zeros(5)) == 0.0


def test_fracture_is_the_last_sample_before_the_sudden_drop():
    force, _ = _loading(2)
    broken = np.concatenate([force, [300.0, 200.0, 250.0, 220.0]])
    assert find_fracture(broken) == force.size - 1
    assert find_fracture(force) is None


@pytest.mark.parametrize("intervals", [1, 2, 5])
def test_a_fracture_logged_over_several_samples_is_the_sample_before_the_fall(intervals):
    """A slow log (a 5 Hz compression test of a real MTS export falls over five samples)
    catches the fall midway: the fracture is still the last sample before it, where the
    simulated pull's truth has it, not one on the way down."""
    for seed in range(5):
        truth = PullTruth.for_chain("18x64", fracture_samples=intervals)
        force = simulate_pull(truth, seed)["force"].to_numpy()
        assert find_fracture(force) == truth.fracture_index - 1


def test_a_real_slow_fracture_is_the_sample_before_the_fall():
    # the last samples of an MTS 793 compressive-strength export at 5 Hz [kN], oriented
    ramp = np.linspace(300.0, 415.13135, 150)
    fall = [415.53741, 376.14471, 249.9745, 133.22809, 46.494553, 1.6429368, -0.24702586,
            -0.2255328, -0.21011196, -0.22306107, -0.20575896]
    assert find_fracture(np.concatenate([ramp, fall]) * 1e3) == ramp.size


def _seating_then_cycles(yields: bool = True) -> tuple[np.ndarray, np.ndarray]:
    """A real modulus test's record [N], [m] (Walter+Bai, 10 Hz; our noise): from 1.6 kN
    into yield at 17 kN (170 µm; or not, as a stiffer specimen), then cycles between 5 and
    17 kN; the extensometer's knife
    edges settle while the first load comes on: it reads 4 µm up, 6 µm back by 6 kN, then
    follows at 430 kN/mm."""
    rng = np.random.default_rng(3)
    first = np.linspace(1.6e3, 17e3, 800)
    cycle = np.concatenate([np.linspace(17e3, 5e3, 240), np.linspace(5e3, 17e3, 240)])
    force = np.concatenate([first, cycle, cycle])
    plastic = np.maximum.accumulate(np.clip((force - 12e3) / 5e3, 0.0, None) ** 2 * 145e-6
                                    * yields)
    extensometer = (force - 6e3) / 430e6 + plastic
    extensometer[:200] = np.interp(np.arange(200), [0, 50, 120, 199],
                                   [0.0, 4e-6, -2e-6, extensometer[199]])
    noise = rng.normal(0.0, 2e-7, force.size)
    return force + rng.normal(0.0, 5.0, force.size), np.round((extensometer + noise) / 1e-7) * 1e-7


def test_an_extensometer_seating_as_the_first_load_comes_on_is_not_taken_off():
    # it was cut from its first sample as running backwards, and E0 came from the machine's
    # travel, 16 times too low
    force, extensometer = _seating_then_cycles()
    assert find_removal(force, extensometer) is None
    # so in cycles below the yield: the 4 µm are a sixth of the elastic travel
    assert find_removal(*_seating_then_cycles(yields=False)) is None
    # one that hangs where it fell, never to follow the force again, was taken off
    hanging = extensometer.copy()
    hanging[50:] = -2e-6 + np.random.default_rng(4).normal(0.0, 2e-7, force.size - 50)
    removal = find_removal(force, hanging)
    assert removal is not None and removal.position <= 60


def test_a_fracture_after_necking_is_the_sample_before_the_break():
    # the last samples of a real steel plate's pull at 1 Hz [kN]: necking sheds 1 to 3 kN a
    # sample, faster and faster, then the plate breaks from 111.88 kN; the fracture had
    # been put at 121.5 kN, 4 samples early, the necking steps taken for the fall's start
    ramp = np.linspace(20.0, 143.9, 400)
    necking = np.linspace(143.9, 134.6, 40)
    last = [134.592, 133.944, 133.224, 132.448, 131.64, 130.728, 129.752, 128.656, 127.504,
            126.2, 124.784, 123.28, 121.504, 119.528, 117.256, 114.856, 111.88, 4.24, 4.232,
            4.232]
    force = np.concatenate([ramp, necking, last]) * 1e3
    assert force[find_fracture(force)] == 111.88e3


def _stopped_hot_pull(shed: float) -> np.ndarray:
    """A real catman pull at 370 °C, 50 Hz [N], oriented: necking from its 7145 N maximum
    to 6257 N, the machine stopped there, the force relaxing by `shed` of it within 0.3 s
    (15 samples), holding the rest for 6 s, then the machine backing off to 229 N."""
    rng = np.random.default_rng(0)
    rise, neck = np.linspace(100.0, 7145.0, 900), np.linspace(7145.0, 6257.0, 60)
    held = 6257.0 * (1.0 - shed * (1.0 - np.exp(-np.arange(1, 301) / 5.0)))
    back = np.linspace(held[-1], 229.0, 300)
    return np.concatenate([rise, neck, held, back]) + rng.normal(0.0, 2.0, 1560)


def test_a_record_that_ends_while_the_force_falls_is_a_fracture():
    # the last samples of a real Bluehill pull at 500 Hz [N]: 18 ms into the fall, at 55 %
    # of the maximum, the machine stopped recording; taken for a test stopped, it was none
    ramp = np.linspace(500.0, 15365.9, 1457)
    fall = [14134.0, 13465.0, 12716.0, 11901.0, 11044.0, 10167.0, 9286.0, 8414.0]
    assert find_fracture(np.concatenate([ramp, fall])) == ramp.size - 1


def test_a_fracture_captured_at_a_higher_rate_is_judged_at_the_loading_rate():
    # the last samples of a real Bluehill rivet pull [s], [N]: logged every 0.1 s, then every
    # 2 to 6 ms once the machine detected the break; the fall of 0.3 s took 25 samples, more
    # than a fracture's span, and the fracture was put 90 N down the fall
    ramp = np.linspace(20.0, 836.56421, 224)
    fall = [837.21625, 832.08575, 810.53033, 780.02155, 747.41772, 716.48602, 680.17712,
            639.9696, 597.08087, 552.56342, 507.28903, 462.02939, 417.42111, 374.01321,
            332.23926, 292.44891, 254.89337, 219.74986, 187.14401, 157.13211, 129.72896,
            93.43412, 62.68209, 37.13066, 10.47543, -15.95855, 0.55094, -0.5131, -0.52896,
            -0.36868, -0.32585, -0.07868, -0.17596, -0.16034]
    capture = np.cumsum([0.027, 0.003] + [0.002] * 16 + [0.003] * 3 + [0.004, 0.006])
    time = np.concatenate([np.arange(227) * 0.1, 22.6 + capture,
                           22.681 + 0.1 * np.arange(1, 9)])
    force = np.concatenate([ramp, fall])
    assert force[find_fracture(force, time)] == pytest.approx(837.2, abs=30.0)
    # stamps rounded so that rows repeat them say nothing of the rate: samples are counted
    assert find_fracture(force, np.round(time, 0)) == find_fracture(force)


def test_a_pull_stopped_near_its_maximum_is_no_fracture():
    # the force shed by the relaxation falls as suddenly as a slow log's fracture, and
    # stops within as many samples; the specimen still carries 85 %: it did not break
    assert find_fracture(_stopped_hot_pull(0.15)) is None
    # the same fall on to a few per cent of the force is one
    assert find_fracture(_stopped_hot_pull(0.97)) == pytest.approx(959, abs=2)


def _set_up_then_loading(seed: int) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """A real MTS 793 compression test's record, in its direction of load [N], [m], [m]:
    the crosshead approaches the specimen at no load (400 samples), the extensometer is
    clipped on and adjusted at a preload of 1.5 % of the maximum after a seating knock to
    9.6 % (its readings jump about, then it is zeroed), and then the loading itself."""
    rng = np.random.default_rng(seed)
    force, extensometer = _loading(seed)
    top = force.max()
    approach = rng.normal(0.0, FORCE_NOISE, 400)
    knock = np.interp(np.arange(100), [0, 10, 30, 100], [0.0, 0.096, 0.015, 0.015]) * top
    hold = 0.015 * top + rng.normal(0.0, FORCE_NOISE, 400)
    adjusting = np.repeat(rng.uniform(-2e-3, 2e-3, 8), 50)  # clipped on, set, zeroed
    set_up_force = np.concatenate([approach, knock, hold])
    set_up_extensometer = np.concatenate([np.full(500, 0.4e-3), adjusting])
    set_up_crosshead = np.concatenate([np.linspace(-5e-3, 0.0, 400), np.zeros(500)])
    travel = 2.0 * np.linspace(0.0, 29e3, force.size) / E0 * GAUGE  # the machine's as much
    crosshead = np.round((travel + rng.normal(0.0, GAUGE_NOISE, force.size)) / 1e-6) * 1e-6
    return (np.concatenate([set_up_force, force]),
            np.concatenate([set_up_extensometer, extensometer]),
            np.concatenate([set_up_crosshead, crosshead]))


@pytest.mark.parametrize("seed", range(5))
def test_the_set_up_before_the_loading_is_not_judged(seed):
    # a real MTS 793 export: every channel was cut in its set-up and the run refused
    force, extensometer, crosshead = _set_up_then_loading(seed)
    assert find_removal(force, extensometer, [crosshead]) is None
    assert find_removal(force, crosshead, [extensometer]) is None


def test_an_extensometer_taken_off_after_the_set_up_is_still_found():
    force, extensometer, crosshead = _set_up_then_loading(0)
    extensometer[5000:] -= 0.5e-3  # falls off, far into the loading
    removal = find_removal(force, extensometer, [crosshead])
    assert removal is not None and removal.reason == "runs backwards"
    assert removal.position == 5000


def test_a_gauge_zeroed_after_a_first_load_cycle_is_judged_on_the_loading_after_it():
    # a real MTS 793 compression test: a first cycle to 28 % of the maximum, unloaded to
    # 0.4 %, the gauges zeroed, then loaded to fracture; the gauges read less on the
    # reloading than at the first peak and were all cut there, "running backwards"
    first_up, down, reload = np.linspace(0, 0.28, 300), np.linspace(0.28, 0.004, 300), \
        np.linspace(0.004, 1.0, 1000)
    force = 400e3 * np.concatenate([first_up, down, reload])
    zeroed = np.concatenate([first_up, down, reload - 0.004]) * 1e-3
    zeroed[:600] += 0.05e-3  # the first cycle's set, taken off by the zeroing
    assert find_removal(force, zeroed) is None


def _dwell(seed: int) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """A loading [N] that dwells a fifth of its record at 20 kN, its extensometer [m] still
    through the dwell, and its crosshead [m] creeping on through it."""
    rng = np.random.default_rng(seed)
    force, extensometer = _loading(seed)
    start = int(np.searchsorted(force, 20e3))
    hold = force.size // 5
    force = np.concatenate([force[:start], 20e3 + rng.normal(0.0, FORCE_NOISE, hold),
                            force[start:]])
    extensometer = np.concatenate([extensometer[:start], np.full(hold, extensometer[start]),
                                   extensometer[start:]])
    travel = 2.0 * extensometer + np.concatenate(
        [np.zeros(start), np.linspace(0.0, 0.5e-3, hold), np.full(force.size - start - hold,
                                                                  0.5e-3)])
    return force, extensometer, travel


def test_an_extensometer_still_while_the_crosshead_moves_on_is_cut():
    force, extensometer, crosshead = _dwell(0)
    removal = find_removal(force, extensometer, [crosshead])
    assert removal is not None and removal.reason == "freezes"


def test_an_extensometer_read_far_into_plastic_strain_moves_with_the_crosshead():
    # a real 1045 steel pull at 2 Hz: 0.15 % elastic strain, 28.6 % at the fracture; 0.5 %
    # of that range was the whole elastic strain, so the extensometer "stood still" while
    # the crosshead (the machine's compliance besides) moved, and E0 came from the crosshead
    # at 5.1 GPa
    elastic = np.linspace(0.0, 25.0, 60)  # kN, up to yield
    hardening = 25.0 + 4.4 * np.sin(np.linspace(0.0, np.pi / 2, 195))
    necking = 29.4 - 10.0 * np.linspace(0.0, 1.0, 125) ** 2
    force = np.concatenate([elastic, hardening, necking])
    strain = np.concatenate([elastic / 1.7e4, 0.0015 + np.linspace(0.0, 0.12, 195),
                             0.1215 + np.linspace(0.0, 0.165, 125)])
    crosshead = 25.4 * strain + force / 20.0  # mm: the specimen and the machine's compliance
    assert find_removal(force, strain, [crosshead]) is None


@pytest.mark.parametrize("seed", range(5))
def test_a_channel_left_unconnected_witnesses_nothing(seed):
    # a real MTS export: auxiliary inputs wandering with their noise, or standing at one
    # reading, beside the displacement; it was cut as frozen while they "moved"
    force, extensometer, _ = _dwell(seed)
    wandering = np.cumsum(np.random.default_rng(seed).normal(0.0, GAUGE_NOISE, force.size))
    standing = np.full(force.size, -1.14e-4)
    assert find_removal(force, extensometer, [wandering, standing]) is None


@pytest.mark.parametrize("seed", range(5))
def test_an_extensometer_settling_back_while_the_force_stands_is_not_taken_off(seed):
    # the knife edges settle at the preload: the reading falls four steps of its
    # resolution while the force stands, then follows the loading
    rng = np.random.default_rng(seed)
    force, channel = _loading(seed)
    standing = 5e3 + rng.normal(0.0, FORCE_NOISE, 200)
    settling = channel[0] + RESOLUTION * np.repeat([2.0, 1.0, 0.0, -1.0, -2.0], 40)
    assert find_removal(np.concatenate([standing, force]),
                        np.concatenate([settling, channel])) is None


def _necking(seed: int) -> tuple[np.ndarray, np.ndarray]:
    """A displacement-controlled pull [N], [m]: the crosshead moves 1 µm a sample; the force
    rises to 2.46 kN, falls slowly as the specimen necks, then sheds 15 % of its maximum
    in the 10 samples before the fracture (a real MTS 793 pull of stainless steel)."""
    rng = np.random.default_rng(seed)
    crosshead = 1e-6 * np.arange(3000) + rng.normal(0.0, 2e-8, 3000)
    force = np.concatenate([2460.0 * np.sqrt(np.linspace(0.0, 1.0, 2000)),
                            np.linspace(2460.0, 2200.0, 990), np.linspace(2190.0, 1830.0, 10)])
    return force + rng.normal(0.0, 1.0, 3000), crosshead


@pytest.mark.parametrize("seed", range(5))
def test_a_crosshead_through_a_fast_fall_before_the_fracture_is_not_frozen(seed):
    # its 10 µm over that fall are within half a per cent of its 3 mm range: it was cut as
    # frozen, and the elongation at fracture was lost
    force, crosshead = _necking(seed)
    assert find_removal(force, crosshead) is None


@pytest.mark.parametrize("seed", range(5))
def test_an_extensometer_taken_off_at_the_maximum_is_frozen_past_it(seed):
    force, crosshead = _necking(seed)
    extensometer = np.round(np.minimum(crosshead, crosshead[2100]) / 1e-7) * 1e-7
    removal = find_removal(force, extensometer)
    assert removal is not None and removal.reason == "freezes"
    # from where it stood within its tolerance (half a per cent of its 3 mm range: 15 µm)
    assert 2085 <= removal.position <= 2100


def test_a_strain_written_back_to_zero_at_the_break_is_cut_there():
    # a real testXpert tear test: past the maximum, the strain is written back to 0 from
    # the first sample of the fall on, and the strain at fracture was read as 0 %
    force = np.concatenate([np.linspace(0.0, 1257.0, 680), [1250.0, 1230.0, 1189.5, 1145.0,
                                                            1085.3]])
    strain = np.concatenate([np.linspace(0.0, 0.0246, 680), [0.02515, 0.0253, 0.02556,
                                                             0.02569, 0.0]])
    removal = find_removal(force, strain)
    assert removal is not None and (removal.position, removal.reason) == (684, "jumps")
