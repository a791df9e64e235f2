package io.concord.bench.harness;

/**
 * {@code <agents> <hosts> <seed>}: one point of the scale simulation in a JVM of its own, with the
 * heap it needs (every simulated agent holds the whole list: 5,000 agents hold 25 million entries),
 * printing the result's fields on a {@code POINT} line.
 */
public final class ScaleChild {
    private ScaleChild() {
    }

    public static void main(String[] args) {
        ScaleHarness.Result r = ScaleHarness.run(Integer.parseInt(args[0]), Integer.parseInt(args[1]), Long.parseLong(args[2]));
        System.out.println("POINT " + r.agents() + " " + r.hosts() + " " + r.converged() + " " + r.convergeMs() + " " + r.healed()
                + " " + r.healMs() + " " + r.msgsPerCyclePerAgent() + " " + r.bytesPerCyclePerAgent() + " " + r.periodMs() + " "
                + r.convergeKbPerAgent() + " " + r.healKbPerAgent() + " " + r.allUpMs() + " " + r.wallS());
        System.exit(0);
    }

    /** Parses a POINT line back. */
    public static ScaleHarness.Result parse(String line) {
        String[] p = line.substring(6).trim().split(" ");
        return new ScaleHarness.Result(Integer.parseInt(p[0]), Integer.parseInt(p[1]), Boolean.parseBoolean(p[2]),
                Double.parseDouble(p[3]), Boolean.parseBoolean(p[4]), Double.parseDouble(p[5]), Double.parseDouble(p[6]),
                Double.parseDouble(p[7]), Double.parseDouble(p[8]), Double.parseDouble(p[9]), Double.parseDouble(p[10]),
                Double.parseDouble(p[11]), Double.parseDouble(p[12]));
    }
}
