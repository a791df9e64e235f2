import jade.content.Concept;
import jade.util.leap.ArrayList;
import jade.util.leap.List;

import java.util.Date;

/** A book, a JavaBean whose authors are a jade.util.leap.List, as JADE's reflective introspector expects. */
public class Book implements Concept {
    private String title;
    private List authors;
    private float price;
    private int pages;
    private Date published;

    public String getTitle() {
        return title;
    }

    public void setTitle(String title) {
        this.title = title;
    }

    public List getAuthors() {
        return authors;
    }

    public void setAuthors(List authors) {
        this.authors = authors;
    }

    public float getPrice() {
        return price;
    }

    public void setPrice(float price) {
        this.price = price;
    }

    public int getPages() {
        return pages;
    }

    public void setPages(int pages) {
        this.pages = pages;
    }

    public Date getPublished() {
        return published;
    }

    public void setPublished(Date published) {
        this.published = published;
    }

    /** Its fields, in a fixed order. */
    public String describe() {
        StringBuilder a = new StringBuilder("[");
        for (int i = 0; authors != null && i < authors.size(); i++) {
            a.append(i == 0 ? "" : ", ").append(authors.get(i));
        }
        return "title=" + title + " authors=" + (authors == null ? "null" : a + "]") + " price=" + price + " pages=" + pages
                + " published=" + (published == null ? "none" : Long.toString(published.getTime()));
    }

    /** A book. */
    public static Book of(String title, float price, int pages, Date published, String... authors) {
        Book b = new Book();
        b.setTitle(title);
        if (authors.length > 0) {
            List l = new ArrayList();
            for (String s : authors) {
                l.add(s);
            }
            b.setAuthors(l);
        }
        b.setPrice(price);
        b.setPages(pages);
        b.setPublished(published);
        return b;
    }
}
