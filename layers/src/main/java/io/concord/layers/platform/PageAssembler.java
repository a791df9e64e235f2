package io.concord.layers.platform;

import java.util.ArrayList;
import java.util.List;

/**
 * Puts a list sent in pages back together (the LAL from a container, the GAL, another host's list),
 * one version at a time: a page of a new version drops the pages of the one before, so at most one
 * version's pages are held.
 */
final class PageAssembler {
    private Object key;
    private List<?>[] pages;

    /**
     * Files one page of the version {@code key}.
     *
     * @return every entry of the list once all its pages are in, else {@code null}
     * @throws IllegalArgumentException if the pages of one version disagree on their count
     */
    List<AgentEntry> add(Object key, PlatformMessage.Page page) {
        if (!key.equals(this.key)) {
            this.key = key;
            pages = new List<?>[page.count()];
        }
        if (pages.length != page.count()) {
            throw new IllegalArgumentException("list pages disagree on their count: " + page.count() + " and " + pages.length);
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
    }
}
