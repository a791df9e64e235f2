package io.concord.testkit;

/**
 * What the virtual network does to datagrams, as probabilities drawn from the simulation's seeded
 * random source: drop, duplicate, reorder (an extra delay that lets later datagrams overtake),
 * corrupt (one bit flipped), and a base latency with jitter. Partitions and crashes are commands
 * on {@link VirtualNetwork} and {@link Simulation}.
 *
 * @param dropRate       probability a datagram is lost
 * @param duplicateRate  probability a datagram is delivered twice
 * @param reorderRate    probability a datagram is held back by up to {@code reorderDelayNs}
 * @param corruptRate    probability one bit of a datagram is flipped
 * @param latencyNs      base one-way latency
 * @param jitterNs       uniform extra latency in {@code [0, jitterNs)}
 * @param reorderDelayNs the largest extra delay of a reordered datagram
 */
public record FaultPlan(double dropRate, double duplicateRate, double reorderRate, double corruptRate,
                        long latencyNs, long jitterNs, long reorderDelayNs) {

    /** A perfect network with 50 µs latency. */
    public static final FaultPlan NONE = new FaultPlan(0, 0, 0, 0, 50_000, 0, 0);

    public FaultPlan {
        check("dropRate", dropRate);
        check("duplicateRate", duplicateRate);
        check("reorderRate", reorderRate);
        check("corruptRate", corruptRate);
        if (latencyNs <= 0 || jitterNs < 0 || reorderDelayNs < 0) {
            throw new IllegalArgumentException("latencyNs must be > 0 and jitterNs, reorderDelayNs >= 0; got "
                    + latencyNs + ", " + jitterNs + ", " + reorderDelayNs);
        }
    }

    private static void check(String name, double p) {
        if (!(p >= 0 && p <= 1)) {
            throw new IllegalArgumentException(name + " must be a probability in [0, 1], got " + p);
        }
    }

    /** A lossy network: the given rates, 50 µs latency, 20 µs jitter, reordering by up to 1 ms. */
    public static FaultPlan lossy(double drop, double duplicate, double reorder, double corrupt) {
        return new FaultPlan(drop, duplicate, reorder, corrupt, 50_000, 20_000, 1_000_000);
    }

    public FaultPlan withLatency(long latencyNs, long jitterNs) {
        return new FaultPlan(dropRate, duplicateRate, reorderRate, corruptRate, latencyNs, jitterNs, reorderDelayNs);
    }
}
