package io.concord.console;

import java.util.ArrayDeque;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.ArrayBlockingQueue;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.atomic.AtomicLong;

/**
 * The browsers that have the console open, and what each one wants: the loop publishes, each
 * browser's own HTTP thread writes. The loop never waits for a browser: each has a bounded queue
 * ({@link #QUEUE} events, {@link #MAX_CHARS} characters), and an event that does not fit is
 * dropped for that browser alone and counted
 * ({@code console-slow-client}). Thread-safe.
 */
final class Hub {
    /** Events waiting for one browser, and their characters at most. */
    static final int QUEUE = 512;
    static final long MAX_CHARS = 4L << 20;

    /** One open event stream. */
    static final class Client {
        final Set<String> topics;
        final Set<String> sniff;
        final String conversation;
        final ArrayBlockingQueue<String> queue = new ArrayBlockingQueue<>(QUEUE);
        final AtomicLong chars = new AtomicLong();
        volatile boolean closed;

        /** The next event to write, waiting at most the time given; {@code null} if none came. */
        String take(long ms) throws InterruptedException {
            String e = queue.poll(ms, java.util.concurrent.TimeUnit.MILLISECONDS);
            if (e != null) {
                chars.addAndGet(-e.length());
            }
            return e;
        }

        Client(Set<String> topics, Set<String> sniff, String conversation) {
            this.topics = topics;
            this.sniff = sniff;
            this.conversation = conversation;
        }

        boolean wantsSniff(String by, String from, String to, String conv) {
            if (!topics.contains("sniff")) {
                return false;
            }
            if (conversation != null) {
                return conversation.equals(conv);
            }
            return sniff.contains(by) || sniff.contains(from) || sniff.contains(to);
        }
    }

    private final List<Client> clients = new CopyOnWriteArrayList<>();
    private final Map<String, String> last = new ConcurrentHashMap<>();
    private final ArrayDeque<String[]> sniffed = new ArrayDeque<>();
    private final int keep;
    private final int maxClients;
    final AtomicLong slowDrops = new AtomicLong();
    /** The recording under way, or {@code null}. */
    private volatile Recorder recorder;
    final AtomicLong refused = new AtomicLong();

    Hub(int keep, int maxClients) {
        this.keep = keep;
        this.maxClients = maxClients;
    }

    /**
     * A new stream: it gets the last event of each of its topics at once, and the kept sniffed
     * messages it selects; {@code null} if {@link #maxClients} are open.
     */
    Client open(Set<String> topics, Set<String> sniff, String conversation) {
        synchronized (clients) {
            if (clients.size() >= maxClients) {
                refused.incrementAndGet();
                return null;
            }
            Client c = new Client(topics, sniff, conversation);
            for (String t : topics) {
                String json = last.get(t);
                if (json != null) {
                    offer(c, frame(t, json));
                }
            }
            synchronized (sniffed) {
                for (String[] s : sniffed) {
                    if (c.wantsSniff(s[0], s[1], s[2], s[3])) {
                        offer(c, s[4]);
                    }
                }
            }
            clients.add(c);
            return c;
        }
    }

    void close(Client c) {
        c.closed = true;
        clients.remove(c);
    }

    int open() {
        return clients.size();
    }

    /** Records every event from now on into {@code r} (or stops, with {@code null}); returns the one it replaces. */
    Recorder record(Recorder r) {
        if (r != null) {
            // A recording starts with where things stand: the last event of each topic.
            long now = System.currentTimeMillis();
            last.forEach((topic, json) -> r.record(now, topic, json));
        }
        Recorder old = recorder;
        recorder = r;
        return old;
    }

    Recorder recorder() {
        return recorder;
    }

    /** True while a recording is under way: every topic is then made as if a browser watched it. */
    boolean recording() {
        Recorder r = recorder;
        return r != null && r.recording();
    }

    /** True if an open stream listens to the topic, or a recording is under way. */
    boolean wants(String topic) {
        if (recording()) {
            return true;
        }
        for (Client c : clients) {
            if (c.topics.contains(topic)) {
                return true;
            }
        }
        return false;
    }

    /** The agents the open streams sniff; {@code all} if one follows a conversation. */
    Set<String> sniffed(Set<String> all) {
        Set<String> s = new LinkedHashSet<>();
        for (Client c : clients) {
            if (!c.topics.contains("sniff")) {
                continue;
            }
            if (c.conversation != null) {
                s.addAll(all);
            } else {
                s.addAll(c.sniff);
            }
        }
        return s;
    }

    /** The last event of a topic, as JSON (for a plain GET), or {@code null}. */
    String last(String topic) {
        return last.get(topic);
    }

    /** Sends an event of a topic to every stream that listens to it; kept for streams opened later. */
    void publish(String topic, String json) {
        Recorder r = recorder;
        if (r != null) {
            r.record(System.currentTimeMillis(), topic, json);
        }
        String event = frame(topic, json);
        last.put(topic, json);
        for (Client c : clients) {
            if (c.topics.contains(topic)) {
                offer(c, event);
            }
        }
    }

    /** A sniffed message, to the streams that selected one of its agents or its conversation; the last {@code keep} are kept. */
    void sniff(String by, String from, String to, String conversation, String json) {
        Recorder r = recorder;
        if (r != null) {
            r.record(System.currentTimeMillis(), "sniff", json);
        }
        String event = frame("sniff", json);
        synchronized (sniffed) {
            sniffed.addLast(new String[] {by, from, to, conversation, event});
            while (sniffed.size() > keep) {
                sniffed.removeFirst();
            }
        }
        for (Client c : clients) {
            if (c.wantsSniff(by, from, to, conversation)) {
                offer(c, event);
            }
        }
    }

    private void offer(Client c, String event) {
        if (c.chars.get() + event.length() > MAX_CHARS || !c.queue.offer(event)) {
            slowDrops.incrementAndGet();
        } else {
            c.chars.addAndGet(event.length());
        }
    }

    static String frame(String topic, String json) {
        return "event: " + topic + "\ndata: " + json + "\n\n";
    }
}
