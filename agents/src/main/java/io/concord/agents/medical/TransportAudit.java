package io.concord.agents.medical;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * The Medical agent's audit trail of transports: who asked for each and when, the chair that took
 * it, when each phase began (the auction won, to the pick-up, loading, to the drop-off,
 * unloading), when and how it ended and why; and its story, each line the agent logged about it
 * (the calls for proposals, every bid and refusal, the award, pauses, phases, the result). The
 * last {@link #KEPT} transports are kept. Thread-safe: the agent writes on its loop, anyone reads.
 */
public final class TransportAudit {
    /** Transports kept; the oldest ended ones go first. */
    public static final int KEPT = 1_000;
    /** Lines of one transport's story kept. */
    public static final int STORY_LINES = 200;
    /** The phases whose start is noted, in order. */
    public static final List<String> PHASES = List.of("awarded", "to-pickup", "loading", "to-dropoff", "unloading");

    /**
     * One transport as far as it has gone.
     *
     * @param task         the Medical agent's id (T1, T2, ...)
     * @param askedBy      the agent that asked (its full name), or the Medical agent's own name when its own code did
     * @param conversation the requester's conversation id (the console's front desk: desk-N), or empty
     * @param askedAtMs    when it was asked, on the agent's clock (epoch ms)
     * @param phases       phase -> when it began (epoch ms), in {@link #PHASES}' order, those reached
     * @param endedAtMs    when it ended, or -1 while open
     * @param outcome      open, done or failed
     * @param reason       why it failed, or empty
     * @param story        what the agent logged about it, each line with its time
     */
    public record Entry(String task, String askedBy, String conversation, long askedAtMs, int from, int to, double priority,
                        String chair, int auctions, Map<String, Long> phases, long endedAtMs, String outcome, String reason,
                        List<Line> story) {
    }

    /** A line of a story and when it was logged (epoch ms). */
    public record Line(long atMs, String text) {
    }

    private static final class Open {
        final String task;
        final String askedBy;
        final String conversation;
        final long askedAtMs;
        final int from;
        final int to;
        final double priority;
        String chair = "";
        int auctions;
        final Map<String, Long> phases = new LinkedHashMap<>();
        long endedAtMs = -1;
        String outcome = "open";
        String reason = "";
        final List<Line> story = new ArrayList<>();

        Open(String task, String askedBy, String conversation, long askedAtMs, int from, int to, double priority) {
            this.task = task;
            this.askedBy = askedBy;
            this.conversation = conversation;
            this.askedAtMs = askedAtMs;
            this.from = from;
            this.to = to;
            this.priority = priority;
        }

        Entry entry() {
            return new Entry(task, askedBy, conversation, askedAtMs, from, to, priority, chair, auctions, Map.copyOf(phases), endedAtMs,
                    outcome, reason, List.copyOf(story));
        }
    }

    private static final Pattern TASK = Pattern.compile("\\b(T\\d+)\\b");
    private final Map<String, Open> byTask = new LinkedHashMap<>();

    synchronized void asked(String task, String askedBy, String conversation, long atMs, int from, int to, double priority) {
        byTask.put(task, new Open(task, askedBy, conversation == null ? "" : conversation, atMs, from, to, priority));
        while (byTask.size() > KEPT) {
            String oldest = byTask.values().stream().filter(o -> o.endedAtMs >= 0).map(o -> o.task).findFirst()
                    .orElse(byTask.keySet().iterator().next());
            byTask.remove(oldest);
        }
    }

    synchronized void auction(String task) {
        Open o = byTask.get(task);
        if (o != null) {
            o.auctions++;
        }
    }

    synchronized void awarded(String task, String chair, long atMs) {
        Open o = byTask.get(task);
        if (o != null) {
            o.chair = chair;
            // Awarded again (the first chair failed or went silent): the later phases start afresh.
            o.phases.clear();
            o.phases.put("awarded", atMs);
        }
    }

    /** A progress report: the phase's start is when it was first reported. */
    synchronized void phase(String task, String chair, String phase, long atMs) {
        Open o = byTask.get(task);
        if (o != null && chair.equals(o.chair) && PHASES.contains(phase)) {
            o.phases.putIfAbsent(phase, atMs);
        }
    }

    synchronized void ended(String task, boolean done, String chair, String reason, long atMs) {
        Open o = byTask.get(task);
        if (o != null && o.endedAtMs < 0) {
            o.endedAtMs = atMs;
            o.outcome = done ? "done" : "failed";
            o.reason = reason == null ? "" : reason;
            if (chair != null) {
                o.chair = chair;
            }
        }
    }

    /** A line the agent logged: added to the story of the task it names. */
    synchronized void logged(String line, long atMs) {
        Matcher m = TASK.matcher(line);
        if (m.find()) {
            Open o = byTask.get(m.group(1));
            if (o != null && o.story.size() < STORY_LINES) {
                o.story.add(new Line(atMs, line));
            }
        }
    }

    /** Every transport kept, oldest first. */
    public synchronized List<Entry> entries() {
        List<Entry> l = new ArrayList<>(byTask.size());
        byTask.values().forEach(o -> l.add(o.entry()));
        return l;
    }

    /** One transport, or {@code null}. */
    public synchronized Entry entry(String task) {
        Open o = byTask.get(task);
        return o == null ? null : o.entry();
    }
}
