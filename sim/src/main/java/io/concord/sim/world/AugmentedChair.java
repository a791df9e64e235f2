package io.concord.sim.world;

import io.concord.agents.chair.ChairDriver;
import io.concord.agents.chair.ChairLayout;
import io.concord.agents.chair.ChairListener;
import io.concord.agents.chair.ChairReadings;
import io.concord.agents.chair.Localiser;
import io.concord.agents.chair.Pose;

/**
 * The dissertation's mixed reality: a real (or emulated) chair whose range readings also see
 * the walls, doors, obstacles and other chairs of a simulated world, as if they stood where its
 * own localisation puts it. The chair's motors and odometry are real; the control agent drives
 * this as it drives any chair, and stops at a virtual obstacle as at a real one. Each reading is
 * the nearer of the real and the virtual distance, per sensor. Confined to the runtime's loop the
 * world is attached to.
 */
public final class AugmentedChair implements ChairDriver {
    private final ChairDriver real;
    private final HospitalWorld world;
    private final Localiser localiser = new Localiser();
    private ChairListener listener;
    private ChairReadings latest;

    /**
     * @param real  the chair whose motors and sensors are real
     * @param world the world whose things are added to its readings (it need not hold the chair)
     */
    public AugmentedChair(ChairDriver real, HospitalWorld world) {
        this.real = real;
        this.world = world;
        real.setListener(new ChairListener() {
            @Override
            public void onReadings(ChairReadings r) {
                latest = augment(r);
                if (listener != null) {
                    listener.onReadings(latest);
                }
            }

            @Override
            public void onOnline(boolean online) {
                if (listener != null) {
                    listener.onOnline(online);
                }
            }

            @Override
            public void onEvent(io.concord.agents.chair.ChairEvent event) {
                if (listener != null) {
                    listener.onEvent(event);
                }
            }
        });
    }

    private ChairReadings augment(ChairReadings r) {
        Pose at = localiser.update(r);
        double[] virtual = world.rangesAt(at, real.layout(), 5);
        double[] ranges = r.ranges();
        for (int i = 0; i < ranges.length && i < virtual.length; i++) {
            ranges[i] = Math.min(ranges[i], virtual[i]);
        }
        return new ChairReadings(r.timeNs(), r.seq(), r.leftTicks(), r.rightTicks(), ranges, r.bumper(), r.batteryVolts(),
                r.emergencyStop(), r.faults(), r.odometry(), r.fix());
    }

    @Override
    public String name() {
        return real.name();
    }

    @Override
    public ChairLayout layout() {
        return real.layout();
    }

    @Override
    public void drive(double leftPercent, double rightPercent) {
        real.drive(leftPercent, rightPercent);
    }

    @Override
    public void stop() {
        real.stop();
    }

    @Override
    public boolean reportsArming() {
        return real.reportsArming();
    }

    @Override
    public void holdMotion() {
        real.holdMotion();
    }

    @Override
    public void releaseMotion() {
        real.releaseMotion();
    }

    @Override
    public void arm() {
        real.arm();
    }

    @Override
    public String whyOffline() {
        return real.whyOffline();
    }

    @Override
    public java.util.Map<String, Long> linkDrops() {
        return real.linkDrops();
    }

    @Override
    public ChairReadings latest() {
        return latest;
    }

    @Override
    public boolean online() {
        return real.online();
    }

    @Override
    public void setListener(ChairListener l) {
        this.listener = l;
    }
}
