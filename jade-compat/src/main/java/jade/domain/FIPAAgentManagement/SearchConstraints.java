package jade.domain.FIPAAgentManagement;

/** Limits on a DF search: how many results (-1: all), how deep, and a search id. */
public class SearchConstraints implements jade.content.Concept {
    private static final long serialVersionUID = 1L;
    private static long ids;
    private Long maxDepth;
    private Long maxResults;
    private String searchId;

    /** No limits and no search id (as JADE's: {@link #renewSearchId()} gives one). */
    public SearchConstraints() {
        // no limits, no search id
    }

    /** A new unique search id. */
    public void renewSearchId() {
        synchronized (SearchConstraints.class) {
            searchId = "s" + (++ids);
        }
    }

    public void setSearchId(String id) {
        searchId = id;
    }

    public String getSearchId() {
        return searchId;
    }

    public void setMaxDepth(Long d) {
        maxDepth = d;
    }

    public Long getMaxDepth() {
        return maxDepth;
    }

    public void setMaxResults(Long r) {
        maxResults = r;
    }

    public Long getMaxResults() {
        return maxResults;
    }
}
