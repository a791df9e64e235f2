package io.concord.sim.world;

import io.concord.agents.map.Point;

import java.util.ArrayList;
import java.util.List;

/**
 * A path travelled, sampled at a steady rate into bounded memory: when full, every other point
 * is dropped and the sampling interval doubles, so a run of any length keeps its whole shape.
 */
public final class Track {
    private final int capacity;
    private final float[] xs;
    private final float[] ys;
    private int size;
    private int every = 1;
    private long offered;

    Track(int capacity) {
        this.capacity = capacity;
        this.xs = new float[capacity];
        this.ys = new float[capacity];
    }

    void offer(double x, double y) {
        if (offered++ % every != 0) {
            return;
        }
        if (size == capacity) {
            for (int i = 0; i < capacity / 2; i++) {
                xs[i] = xs[2 * i];
                ys[i] = ys[2 * i];
            }
            size = capacity / 2;
            every *= 2;
        }
        xs[size] = (float) x;
        ys[size] = (float) y;
        size++;
    }

    /** Points kept. */
    public int size() {
        return size;
    }

    /** Point i. */
    public Point get(int i) {
        return new Point(xs[i], ys[i]);
    }

    /** Every point kept, oldest first. */
    public List<Point> points() {
        List<Point> out = new ArrayList<>(size);
        for (int i = 0; i < size; i++) {
            out.add(get(i));
        }
        return out;
    }

    /** Length of the path, metres. */
    public double length() {
        double l = 0;
        for (int i = 1; i < size; i++) {
            l += Math.hypot(xs[i] - xs[i - 1], ys[i] - ys[i - 1]);
        }
        return l;
    }
}
