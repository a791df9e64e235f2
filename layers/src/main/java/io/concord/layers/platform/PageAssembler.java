package io.concord.layers.platform;

import java.util.ArrayList;
import java.util.List;

/**
 * Puts a list sent in pages back together (the LAL from a container, the GAL, another host's list),
 * one version at a time: a page of a new version drops the pages of the one before, so at most one
 * version's pages are held, and at most {@link #MAX_BYTES} of them.
 */
final class PageAssembler {
    /** The pages of one version held at most, in bytes of their text: a list of some 20,000 agents. */
    static final int MAX_BYTES = 4 << 20;
    private Object key;
    private List<?>[] pages;
    private long bytes;

    /**
     * Files one page of the version {@code key}.
     *
     * @return every entry of the list once all its pages are in, else {@code null}
     * @throws IllegalArgumentException if the pages of one version disagree on their count
     * @throws PlatformLimit if the version's pages grow past {@link #MAX_BYTES}: they are dropped
     */
    List<AgentEntry> add(Object key, PlatformMessage.Page page) {
        if (!key.equals(this.key)) {
            this.key = key;
            pages = new List<?>[page.count()];
            bytes = 0;
        }
        if (pages.length != page.count()) {
            throw new IllegalArgumentException("list pages disagree on their count: " + page.count() + " and " + pages.length);
        }
        if (pages[page.index()] == null) {
            bytes += page.body().length();
            if (bytes > MAX_BYTES) {
                clear();
                throw new PlatformLimit("list-too-large", "a list's pages hold more than " + MAX_BYTES
                        + " bytes before the last arrived: the version is dropped");
            }
        }
        pages[page.index()] = page.entries();
        List<AgentEntry> all = new ArrayList<>();
        for (List<?> p : pages) {
            if (p == null) {
                return null;
            }
            for (Object e : p) {
                all.add((AgentEntry) e);
            }
        }
        clear();
        return all;
    }

    void clear() {
        key = null;
        pages = null;
        bytes = 0;
    }
}
